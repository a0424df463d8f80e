#include "viscous_spring.h"
#include <cmath>
#include <stdexcept>

namespace damseis::boundary
{
double Rock::lambda() const
{
  const double lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  return plane_stress ? 2.0 * lam * G() / (lam + 2.0 * G()) : lam;
}

double Rock::cp() const
{
  return std::sqrt(p_modulus() / rho);
}

double Rock::cs() const
{
  return std::sqrt(G() / rho);
}

SpringFactors SpringFactors::recommended(int dim)
{
  return dim == 3 ? SpringFactors{4.0 / 3.0, 2.0 / 3.0}
                  : SpringFactors{1.0, 0.5};
}

SpringDashpot viscous_spring(const Rock& rock, double R, SpringFactors f)
{
  if (!(R > 0.0) || !(rock.rho > 0.0) || !(rock.E > 0.0))
    throw std::invalid_argument(
        "viscous-spring boundary: needs R > 0 and a rock with mass");
  const double G = rock.G();
  return {f.normal * G / R, f.tangential * G / R, rock.rho * rock.cp(),
          rock.rho * rock.cs()};
}
} // namespace damseis::boundary
