#include "sgmp/batch/out_pattern.hpp"

#include "sgmp/pack/parameter_error.hpp"

#include <algorithm>
#include <stdexcept>

#include "sgmp/pack/input_error.hpp"

namespace sgmp::batch {

OutPattern::OutPattern(std::string_view pattern, const Plan& plan) {
    const auto refuse = [&](const std::string& rule) {
        throw ParameterError("out_pattern", printable(pattern), rule);
    };
    if (pattern.empty()) {
        refuse("must name the pack files, e.g. packs/{arrangement}/n{count}-s{seed}.xyz.gz");
    }
    std::string literal;
    const auto flush = [&] {
        if (!literal.empty()) {
            pieces_.push_back({literal, kLiteral});
            literal.clear();
        }
    };
    std::vector<bool> used(parameters().size(), false);
    bool seed = false;
    bool job = false;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        const char c = pattern[i];
        if ((c == '{' || c == '}') && i + 1 < pattern.size() && pattern[i + 1] == c) {
            literal.push_back(c);
            ++i;
            continue;
        }
        if (c == '}') {
            refuse("a '}' closes no placeholder (write }} for a brace)");
        }
        if (c != '{') {
            literal.push_back(c);
            continue;
        }
        const std::size_t close = pattern.find('}', i);
        if (close == std::string_view::npos) {
            refuse("a '{' is never closed (write {{ for a brace)");
        }
        const std::string name(pattern.substr(i + 1, close - i - 1));
        flush();
        if (name == "seed") {
            pieces_.push_back({"", kSeed});
            seed = true;
        } else if (name == "job") {
            pieces_.push_back({"", kJob});
            job = true;
        } else if (const std::size_t index = parameter_index(name); index != std::string::npos) {
            pieces_.push_back({"", index});
            used[index] = true;
        } else {
            refuse("{" + name +
                   "} is no placeholder; use {seed}, {job} or a parameter such "
                   "as {count}, {arrangement}, {relax}");
        }
        i = close;
    }
    flush();
    if (job) {
        return;
    }
    if (plan.seeds.size() > 1 && !seed) {
        refuse("must hold {seed} (or {job}): the batch has several seeds");
    }
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (plan.varies[i] && !used[i]) {
            refuse("must hold {" + parameters()[i].name +
                   "} (or {job}): the batch gives it several values");
        }
    }
}

std::string OutPattern::expand(const Plan& plan, std::size_t job) const {
    std::string name;
    const ParameterValues& values = plan.values(job);
    for (const Piece& piece : pieces_) {
        if (piece.field == kLiteral) {
            name += piece.text;
        } else if (piece.field == kSeed) {
            name += std::to_string(plan.seed(job));
        } else if (piece.field == kJob) {
            name += std::to_string(job);
        } else {
            name += values[piece.field];
        }
    }
    return name;
}

}  // namespace sgmp::batch
