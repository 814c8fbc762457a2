#pragma once
/// @file parameter_error.hpp
/// The one error a library raises for a parameter that breaks its rule.
///
/// A ParameterError carries the parameter's name as the libraries and the pack headers
/// spell it (`phi_target`, `relax_stiffness`), the value as text, and the rule it breaks.
/// Each command line turns the name into its own option spelling (sgmp/cli/run_main.hpp),
/// so no library knows how an option is typed.
#include <stdexcept>
#include <string>

namespace sgmp {

class ParameterError : public std::invalid_argument {
  public:
    ParameterError(std::string name, std::string value, std::string rule)
        : std::invalid_argument(name + " = " + value + ": " + rule),
          name_(std::move(name)),
          value_(std::move(value)),
          rule_(std::move(rule)) {}

    [[nodiscard]] const std::string& name() const { return name_; }
    [[nodiscard]] const std::string& value() const { return value_; }
    [[nodiscard]] const std::string& rule() const { return rule_; }

  private:
    std::string name_;
    std::string value_;
    std::string rule_;
};

}  // namespace sgmp
