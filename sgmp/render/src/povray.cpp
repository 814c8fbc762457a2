#include "sgmp/render/povray.hpp"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/child_process.hpp"
#include "sgmp/pack/executables.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/render/png_info.hpp"

namespace sgmp::render {
namespace fs = std::filesystem;
namespace {

/// Bound on one render's wall-clock time.
constexpr double kTimeoutSeconds = 900.0;

/// A fresh scratch directory, removed with everything in it when this goes out of scope.

/// POV-Ray's most telling line: the last that mentions an error, else the last non-empty.
std::string reason(const std::deque<std::string>& lines) {
    for (auto it = lines.rbegin(); it != lines.rend(); ++it) {
        if (it->find("rror") != std::string::npos) {
            return *it;
        }
    }
    for (auto it = lines.rbegin(); it != lines.rend(); ++it) {
        if (!it->empty()) {
            return *it;
        }
    }
    return "no output";
}

}  // namespace

std::optional<fs::path> find_povray() {
    if (const char* chosen = std::getenv("SGMP_POVRAY")) {
        if (*chosen == '\0') {
            return std::nullopt;
        }
        return find_executable(chosen);
    }
    return find_executable("povray");
}

bool key_font_found() {
    for (const char* folder :
         {"/usr/share/povray-3.7/include", "/usr/local/share/povray-3.7/include",
          "/usr/share/povray/include", "/usr/local/share/povray/include"}) {
        std::error_code error;
        if (fs::exists(fs::path(folder) / "cyrvetic.ttf", error)) {
            return true;
        }
    }
    return false;
}

std::string povray_missing_note() {
    return "POV-Ray was not found (install the Debian package povray), so no pictures were "
           "rendered";
}

void render_png(const fs::path& povray, const RenderJob& job) {
    check_writable(job.out, job.overwrite);
    const ScratchDirectory scratch("sgmp-render");
    {
        std::ofstream scene(scratch.path() / "scene.pov", std::ios::binary);
        scene << job.scene;
        if (!scene.flush()) {
            throw std::runtime_error(scratch.path().string() + ": cannot write the scene");
        }
    }
    ChildOptions options;
    options.argv = {povray.string(),
                    "+Iscene.pov",
                    "+Oimage.png",
                    "+W" + std::to_string(job.width),
                    "+H" + std::to_string(job.height),
                    "+FN",
                    "-D",
                    "-P",
                    "+Q9",
                    "+A0.3",
                    "+AM2",
                    "+R3",
                    "-GS",
                    "-GR"};
    if (job.threads > 0) {
        options.argv.push_back("+WT" + std::to_string(job.threads));
    }
    options.working_directory = scratch.path();
    options.timeout = std::chrono::duration<double>(kTimeoutSeconds);
    std::deque<std::string> lines;
    const auto result = run_child(options, [&](const std::string& line) {
        lines.push_back(line);
        if (lines.size() > 40) {
            lines.pop_front();
        }
    });
    if (result.end == ChildEnd::timed_out) {
        throw std::runtime_error("povray took longer than " +
                                 std::to_string(static_cast<int>(kTimeoutSeconds)) + " s");
    }
    if (result.end == ChildEnd::signalled) {
        throw std::runtime_error("povray was killed by signal " + std::to_string(result.signal) +
                                 " (" + strsignal(result.signal) + "): " + reason(lines));
    }
    if (result.end == ChildEnd::stopped) {
        throw std::runtime_error("povray was stopped before it finished");
    }
    if (result.exit_code != 0) {
        throw std::runtime_error("povray failed (exit " + std::to_string(result.exit_code) +
                                 "): " + reason(lines));
    }
    const std::string image = read_text_file(scratch.path() / "image.png");
    const auto size = png_size(image);
    if (!size || size->width != static_cast<std::uint32_t>(job.width) ||
        size->height != static_cast<std::uint32_t>(job.height)) {
        throw std::runtime_error("povray did not write a " + std::to_string(job.width) + "x" +
                                 std::to_string(job.height) + " PNG: " + reason(lines));
    }
    const std::string tagged = with_text_chunks(image, job.texts);
    write_file_atomically(job.out, job.overwrite,
                          [&](std::ostream& out) { out.write(tagged.data(), tagged.size()); });
}

}  // namespace sgmp::render
