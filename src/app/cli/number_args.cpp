#include "number_args.h"

#include "physltl/scenario/world.h"

#include <cerrno>
#include <cstdlib>
#include <string>

namespace physltl::app {

CLI::Validator number_in(double lo, double hi, bool lo_allowed) {
  return CLI::Validator(
      [lo, hi, lo_allowed](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return "'" + text + "' is not a number";
        const auto problem = scenario::number_problem(value, lo, hi, lo_allowed);
        return problem ? "'" + text + "' " + *problem : "";
      },
      "NUMBER");
}

CLI::Validator whole_in(long long lo, long long hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const size_t digits_from = !text.empty() && text.front() == '-' ? 1 : 0;
        const bool digits = text.size() > digits_from && text.size() <= 19 &&
                            text.find_first_not_of("0123456789", digits_from) == std::string::npos;
        if (!digits) return "'" + text + "' is not a whole number";
        const long long value = std::strtoll(text.c_str(), nullptr, 10);
        if (value < lo) return "'" + text + "' must be at least " + std::to_string(lo);
        if (value > hi) return "'" + text + "' is too large (at most " + std::to_string(hi) + ")";
        return "";
      },
      "INTEGER");
}

CLI::Validator seed_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const bool digits = !text.empty() && text.size() <= 20 && text.find_first_not_of("0123456789") == std::string::npos;
        errno = 0;
        if (digits) std::strtoull(text.c_str(), nullptr, 10);
        if (!digits || errno == ERANGE) return "a seed is a whole number from 0 to 18446744073709551615, got '" + text + "'";
        return "";
      },
      "SEED");
}

}  // namespace physltl::app
