#pragma once
/// @file executables.hpp
/// Finding the programs a pour runs.

#include <filesystem>
#include <optional>
#include <string>

namespace sgmp {

/// `name` itself when it contains a '/', else the first executable file of that name in
/// the directories of $PATH, made absolute (so it runs from any working directory);
/// nullopt when there is none.
std::optional<std::filesystem::path> find_executable(const std::string& name);

}  // namespace sgmp
