#include <fcntl.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "temporary_names.hpp"

namespace sgmp {
namespace fs = std::filesystem;

namespace {

/// Largest output record read back (a report has a few hundred entries; a larger file
/// is no record of ours and protects nothing).
constexpr std::uintmax_t kMaxRecordBytes = 1 << 20;

std::runtime_error path_error(const fs::path& path, const std::string& reason) {
    return std::runtime_error(path.string() + ": " + reason);
}

/// `message` with every mention of the temporary directory `temporary` as `target`.
std::string as_output(std::string message, const fs::path& temporary, const fs::path& target) {
    const std::string from = temporary.string();
    const std::string to = target.string();
    for (std::size_t at = message.find(from); at != std::string::npos;
         at = message.find(from, at + to.size())) {
        message.replace(at, from.size(), to);
    }
    return message;
}

/// Every entry under `directory` (files, links and subdirectories, never through a
/// link), as relative paths with '/' separators.
std::set<std::string> entries_of(const fs::path& directory) {
    std::set<std::string> entries;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(directory)) {
        entries.insert(entry.path().lexically_relative(directory).generic_string());
    }
    return entries;
}

/// The entries listed in `directory`'s output record, or none when it has no readable
/// record of ours (a link, too large, or a path leaving the directory).
std::set<std::string> recorded_entries(const fs::path& directory) {
    const fs::path record = directory / kOutputRecord;
    std::error_code error;
    const fs::file_status status = fs::symlink_status(record, error);
    if (error || !fs::is_regular_file(status) || fs::file_size(record, error) > kMaxRecordBytes ||
        error) {
        return {};
    }
    std::ifstream in(record, std::ios::binary);
    std::set<std::string> entries;
    for (std::string line; std::getline(in, line);) {
        const fs::path entry(line);
        if (line.empty() || line.front() == '#' || entry.is_absolute() ||
            line.find("..") != std::string::npos) {
            continue;
        }
        entries.insert(entry.lexically_normal().generic_string());
    }
    return entries;
}

/// Writes the record of what `temporary` holds (the record itself included).
void write_record(const fs::path& temporary) {
    std::set<std::string> entries = entries_of(temporary);
    entries.insert(kOutputRecord);
    std::ostringstream text;
    text << "# the outputs this directory was written with; --force replaces only these\n";
    for (const std::string& entry : entries) {
        text << entry << '\n';
    }
    write_text_file(temporary / kOutputRecord, text.str());
}

/// True when `directory` is the current directory or one of its ancestors.
bool holds_current_directory(const fs::path& directory) {
    std::error_code error;
    const fs::path here = fs::weakly_canonical(fs::current_path(), error);
    const fs::path there = fs::weakly_canonical(directory, error);
    if (error) {
        return false;
    }
    const auto [mismatch, _] = std::mismatch(there.begin(), there.end(), here.begin(), here.end());
    return mismatch == there.end();
}

/// Refuses to replace `target` unless it is a directory (not a link, not the current
/// directory or above it): checked before any work.
void check_replaceable_kind(const fs::path& target) {
    const fs::file_status status = fs::symlink_status(target);
    if (fs::is_symlink(status)) {
        throw path_error(target,
                         "is a symbolic link; --force replaces only a directory this "
                         "command wrote, so name that directory itself");
    }
    if (!fs::is_directory(status)) {
        throw path_error(target,
                         "exists and is not a directory of outputs; --force does not "
                         "replace it: choose another --out");
    }
    if (holds_current_directory(target)) {
        throw path_error(target,
                         "is the current directory or holds it; --force does not "
                         "replace it: choose a directory for the outputs alone");
    }
}

/// Refuses to replace `target` unless it is a directory holding only what `owned` names
/// (the new outputs) or its record names: --force replaces outputs, never other files.
void check_replaceable(const fs::path& target, const std::set<std::string>& owned) {
    check_replaceable_kind(target);
    std::set<std::string> allowed = recorded_entries(target);
    allowed.insert(owned.begin(), owned.end());
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(target)) {
        const std::string name = entry.path().lexically_relative(target).generic_string();
        if (allowed.count(name) == 0) {
            throw path_error(target, "holds " + name +
                                         ", which this command did not write; --force replaces "
                                         "only its own outputs: choose another --out");
        }
    }
}

/// Puts the finished directory `temporary` in place of `target`.
void swap_into_place(const fs::path& temporary, const fs::path& target, bool overwrite) {
    std::error_code ignored;
    if (!fs::exists(fs::symlink_status(target))) {
        fs::rename(temporary, target);
        return;
    }
    if (!overwrite) {
        throw FileExists(target);
    }
    check_replaceable(target, entries_of(temporary));
    const fs::path old = sibling_temporary(target, "old");
    fs::remove_all(old, ignored);
    fs::rename(target, old);
    fs::rename(temporary, target);
    fs::remove_all(old, ignored);
}

}  // namespace

void write_directory_atomically(const fs::path& target, bool overwrite,
                                const std::function<void(const fs::path&)>& produce) {
    check_writable(target, overwrite);
    if (overwrite && fs::exists(fs::symlink_status(target))) {
        check_replaceable_kind(target);  // refused before any work
    }
    const fs::path temporary = sibling_temporary(target, "tmp");
    std::error_code ignored;
    const TemporaryGuard guard(temporary, [&] {
        fs::remove_all(temporary, ignored);  // a leftover or a planted link, never followed
        if (::mkdir(temporary.c_str(), 0777) != 0) {
            throw path_error(target, std::string("cannot create a directory beside it: ") +
                                         std::strerror(errno));
        }
    });
    try {
        try {
            produce(temporary);
        } catch (const std::runtime_error& error) {
            // A file of the temporary is named as the output it was for (the temporary
            // is gone when the message is read); other errors pass unchanged.
            if (std::string_view(error.what()).find(temporary.string()) == std::string::npos) {
                throw;
            }
            throw std::runtime_error(as_output(error.what(), temporary, target));
        }
        write_record(temporary);
        swap_into_place(temporary, target, overwrite);
        sync_directory(parent_of(target));
    } catch (...) {
        fs::remove_all(temporary, ignored);
        throw;
    }
}

}  // namespace sgmp
