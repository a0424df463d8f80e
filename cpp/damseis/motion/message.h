/// @file message.h
/// Pieces of the error messages of motion/ (internal to the module).
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace damseis::motion
{
/// A number as the messages show it (6 significant digits).
inline std::string number_text(double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}

/// Throws std::invalid_argument(what) unless ok.
inline void require_argument(bool ok, const std::string& what)
{
  if (!ok)
    throw std::invalid_argument(what);
}
} // namespace damseis::motion
