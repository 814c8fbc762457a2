#include "sgmp/pack/line_reader.hpp"

namespace sgmp {

bool LineReader::next(std::string& line) {
    if (pushed_) {
        line = std::move(*pushed_);
        pushed_.reset();
        ++line_number_;
        return true;
    }
    if (!std::getline(in_, line)) {
        if (in_.bad()) {
            throw InputError(source_, line_number_, "read error");
        }
        return false;
    }
    if (!line.empty() && line.back() == '\r') {
        line.pop_back();
    }
    ++line_number_;
    return true;
}

bool LineReader::at_end() {
    return !pushed_ && in_.peek() == std::istream::traits_type::eof();
}

void LineReader::put_back(std::string line) {
    pushed_ = std::move(line);
    --line_number_;
}

}  // namespace sgmp
