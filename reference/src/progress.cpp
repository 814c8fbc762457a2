#include "sgmp/reference/progress.hpp"

#include <charconv>
#include <sstream>
#include <vector>

namespace sgmp::reference {
namespace {

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string word; in >> word;) {
        out.push_back(word);
    }
    return out;
}

std::optional<double> number(const std::string& text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) {
        return std::nullopt;
    }
    return value;
}

std::optional<std::int64_t> integer(const std::string& text) {
    const auto value = number(text);
    if (!value) {
        return std::nullopt;
    }
    return static_cast<std::int64_t>(*value);
}

/// "LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0, compiled ...)" gives "3.8.0".
std::string banner_version(const std::string& line) {
    const auto w = words(line);
    for (std::size_t i = 0; i + 1 < w.size(); ++i) {
        if (w[i].rfind("LIGGGHTS-", 0) == 0) {
            std::string v = w[i + 1];
            while (!v.empty() && (v.back() == ',' || v.back() == ')')) {
                v.pop_back();
            }
            return v;
        }
    }
    return "unknown";
}

}  // namespace

bool PourLog::take(const std::string& line) {
    if (line.rfind("LIGGGHTS (", 0) == 0 && liggghts_version.empty()) {
        liggghts_version = banner_version(line);
        return false;
    }
    if (line.rfind("ERROR", 0) == 0 && first_error.empty()) {
        first_error = line;
        return false;
    }
    if (line.rfind("SGMP-", 0) != 0) {
        return false;
    }
    const auto w = words(line);
    const std::string& tag = w[0];
    if (tag == "SGMP-PARAMETERS") {
        for (std::size_t i = 1; i + 1 < w.size(); i += 2) {
            if (w[i] == "timestep") {
                timestep = number(w[i + 1]);
            } else if (w[i] == "rayleigh_time") {
                rayleigh_time = number(w[i + 1]);
            } else if (w[i] == "step_cap") {
                step_cap = integer(w[i + 1]);
            }
        }
        return false;
    }
    if (tag == "SGMP-INSERTED" && w.size() >= 2) {
        inserted = integer(w[1]);
        return false;
    }
    if (tag == "SGMP-FALL" && w.size() >= 4) {
        progress.phase = PourPhase::falling;
        progress.step = steps = integer(w[1]).value_or(0);
        progress.phase_steps = integer(w[2]).value_or(0);
        progress.ke_ratio = ke_ratio = number(w[3]).value_or(0.0);
        return true;
    }
    if (tag == "SGMP-SETTLE" && w.size() >= 4) {
        progress.phase = PourPhase::settling;
        progress.step = steps = integer(w[1]).value_or(0);
        progress.phase_steps = step_cap.value_or(0);
        progress.ke_ratio = ke_ratio = number(w[2]).value_or(0.0);
        progress.threshold = number(w[3]).value_or(0.0);
        return true;
    }
    if (tag == "SGMP-RESULT" && w.size() >= 4) {
        settled = w[1] == "settled";
        steps = integer(w[2]).value_or(0);
        ke_ratio = number(w[3]).value_or(0.0);
        return false;
    }
    if (tag == "SGMP-DONE") {
        done = true;
        progress.phase = PourPhase::finished;
        return true;
    }
    return false;
}

}  // namespace sgmp::reference
