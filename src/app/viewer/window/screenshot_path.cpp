// screenshot_path.cpp - the Pictures folder and a screenshot name that is free.
#include "app/viewer/window/screenshot_path.h"

#include <cstdlib>
#include <fstream>

namespace app {
namespace {

// XDG_PICTURES_DIR="$HOME/Pictures": the form xdg-user-dirs writes (a quoted value, absolute
// or starting with $HOME/); nullopt when the file or the line is missing.
std::optional<std::string> userDirsPictures(const std::filesystem::path& file,
                                            const std::string& home) {
    std::ifstream in(file);
    const std::string key = "XDG_PICTURES_DIR=";
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(key, 0) != 0) continue;
        std::string value = line.substr(key.size());
        if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
            value = value.substr(1, value.size() - 2);
        if (value.rfind("$HOME", 0) == 0) value = home + value.substr(5);
        return value;
    }
    return std::nullopt;
}

bool isFolder(const std::filesystem::path& path) {
    std::error_code error;
    return !path.empty() && std::filesystem::is_directory(path, error);
}

} // namespace

Environment processEnvironment() {
    return [](const char* name) -> std::optional<std::string> {
        const char* value = std::getenv(name);
        if (!value || !*value) return std::nullopt;
        return std::string(value);
    };
}

std::filesystem::path picturesFolder(const Environment& env) {
    const std::string home = env("HOME").value_or("");
    if (const auto dir = env("XDG_PICTURES_DIR"); dir && isFolder(*dir)) return *dir;
    const std::filesystem::path config =
        env("XDG_CONFIG_HOME").value_or(home.empty() ? "" : home + "/.config");
    if (!config.empty())
        if (const auto dir = userDirsPictures(config / "user-dirs.dirs", home);
            dir && isFolder(*dir))
            return *dir;
    if (!home.empty() && isFolder(home + "/Pictures")) return home + "/Pictures";
    return ".";
}

std::filesystem::path screenshotPath(const std::filesystem::path& folder, std::time_t when) {
    std::tm local{};
    localtime_r(&when, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "idview-%Y%m%d-%H%M%S", &local);
    std::filesystem::path path = folder / (std::string(stamp) + ".png");
    std::error_code error;
    for (int n = 2; std::filesystem::exists(path, error); ++n)
        path = folder / (std::string(stamp) + "-" + std::to_string(n) + ".png");
    return path;
}

} // namespace app
