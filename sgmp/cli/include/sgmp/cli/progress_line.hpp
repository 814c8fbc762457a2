#pragma once
/// @file progress_line.hpp
/// The one progress printer of the command lines, on stderr: on a terminal the line is
/// rewritten in place; otherwise (a log file, a batch job) a line is printed when the
/// text's kind changes or at most every `interval`, so logs of long runs stay short.
#include <chrono>
#include <string>

namespace sgmp::cli {

class ProgressLine {
  public:
    using Clock = std::chrono::steady_clock;

    /// `quiet` prints nothing; `delay` holds back the first line (short runs stay silent).
    explicit ProgressLine(bool quiet = false, Clock::duration interval = std::chrono::seconds(5),
                          Clock::duration delay = Clock::duration::zero());

    /// Shows `text`; `kind` names its phase (a new kind always prints in a log).
    void update(const std::string& text, int kind = 0);
    /// Ends a line rewritten in place, so later output starts on a fresh line.
    void finish();
    /// Seconds since construction.
    [[nodiscard]] double seconds() const;

  private:
    bool quiet_;
    bool tty_;
    Clock::duration interval_;
    Clock::duration delay_;
    Clock::time_point start_;
    Clock::time_point last_{};
    int last_kind_ = -1;
    bool shown_ = false;
};

}  // namespace sgmp::cli
