#include "sgmp/cli/progress_line.hpp"

#include <unistd.h>

#include <iostream>

#include "sgmp/pack/input_error.hpp"

namespace sgmp::cli {

ProgressLine::ProgressLine(bool quiet, Clock::duration interval, Clock::duration delay)
    : quiet_(quiet),
      tty_(isatty(STDERR_FILENO) == 1),
      interval_(interval),
      delay_(delay),
      start_(Clock::now()) {}

void ProgressLine::update(const std::string& text, int kind) {
    const Clock::time_point now = Clock::now();
    if (quiet_ || now - start_ < delay_) {
        return;
    }
    if (tty_) {
        std::cerr << "\r\033[K" << printable(text) << std::flush;
        shown_ = true;
    } else if (kind != last_kind_ || now - last_ >= interval_) {
        std::cerr << printable(text) << '\n';
        last_ = now;
    }
    last_kind_ = kind;
}

void ProgressLine::finish() {
    if (shown_) {
        std::cerr << '\n';
        shown_ = false;
    }
}

double ProgressLine::seconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
}

}  // namespace sgmp::cli
