#pragma once
/// @file out_pattern.hpp
/// Output names of a sweep's packs: a pattern such as
/// `packs/{arrangement}/n{count}-s{seed}.xyz.gz` in which `{seed}`, `{job}` (the job's
/// number, plan.hpp) and `{NAME}` for any parameter (snake_case or kebab-case, e.g.
/// `{relax}`, `{phi-target}`) stand for the job's values. `{{` and `}}` are literal braces.

#include <string>
#include <string_view>

#include "sgmp/batch/plan.hpp"

namespace sgmp::batch {

class OutPattern {
  public:
    /// Parses `pattern` for `plan`. Throws std::invalid_argument "--out-pattern PATTERN:
    /// rule" for an unknown or unclosed placeholder, and when the names would not tell the
    /// jobs apart: with several seeds the pattern must hold {seed} (or {job}), and every
    /// parameter given more than one value must appear (or {job}).
    OutPattern(std::string_view pattern, const Plan& plan);

    /// The output name of job `job` of the plan.
    [[nodiscard]] std::string expand(const Plan& plan, std::size_t job) const;

  private:
    struct Piece {
        std::string text;  // literal text, when field is kLiteral
        std::size_t field = 0;
    };
    static constexpr std::size_t kLiteral = static_cast<std::size_t>(-1);
    static constexpr std::size_t kSeed = static_cast<std::size_t>(-2);
    static constexpr std::size_t kJob = static_cast<std::size_t>(-3);
    std::vector<Piece> pieces_;
};

}  // namespace sgmp::batch
