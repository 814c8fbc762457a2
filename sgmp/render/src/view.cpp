#include "sgmp/render/view.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

namespace sgmp::render {
namespace {

std::optional<double> number(std::string_view text) {
    double value = 0.0;
    const auto* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

}  // namespace

std::optional<View> parse_view(std::string_view text) {
    if (text == "front") {
        return View{0.0, 10.0};
    }
    if (text == "top") {
        return View{0.0, 90.0};
    }
    if (text == "iso") {
        return View{35.0, 30.0};
    }
    const auto comma = text.find(',');
    if (comma == std::string_view::npos) {
        return std::nullopt;
    }
    const auto azimuth = number(text.substr(0, comma));
    const auto elevation = number(text.substr(comma + 1));
    if (!azimuth || !elevation || *elevation < -90.0 || *elevation > 90.0) {
        return std::nullopt;
    }
    return View{*azimuth, *elevation};
}

Vec3 toward_camera(const View& view) {
    const double a = radians(view.azimuth);
    const double e = radians(view.elevation);
    return Vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
}

Vec3 horizontal_toward_camera(const View& view) {
    const double a = radians(view.azimuth);
    return Vec3(std::sin(a), 0.0, std::cos(a));
}

}  // namespace sgmp::render
