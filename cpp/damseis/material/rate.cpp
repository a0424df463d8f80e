#include "rate.h"

namespace damseis::material
{

namespace
{
constexpr double fcmo = 10e6; // Pa
double alpha_s(double fcm)
{
  return 1.0 / (5.0 + 9.0 * fcm / fcmo);
}
double delta_s(double fcm)
{
  return 1.0 / (10.0 + 6.0 * fcm / fcmo);
}
} // namespace

double ceb_exponent_compression(double fcm)
{
  return 1.026 * alpha_s(fcm);
}
double ceb_exponent_tension(double fcm)
{
  return 1.016 * delta_s(fcm);
}

double ceb_dif_compression(double rate, double fcm)
{
  if (rate <= 30.0)
    return std::pow(rate / ceb_reference_rate_compression,
                    ceb_exponent_compression(fcm));
  const double gamma_s = std::pow(10.0, 6.156 * alpha_s(fcm) - 2.0);
  return gamma_s * std::cbrt(rate);
}

double ceb_dif_tension(double rate, double fcm)
{
  if (rate <= 30.0)
    return std::pow(rate / ceb_reference_rate_tension,
                    ceb_exponent_tension(fcm));
  const double beta_s = std::pow(10.0, 7.11 * delta_s(fcm) - 2.33);
  return beta_s * std::cbrt(rate / ceb_reference_rate_tension);
}

} // namespace damseis::material
