// cad_test_parts.h - what the CAD tests share: a box with a through hole built with Open
// CASCADE and written as a BREP file (loaded then as a user's file would be),
// XDG_CACHE_HOME pointed at a private folder for the life of a test, and scratch folders.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <gp_Ax2.hxx>

namespace cadtest {

// A dx x dy x dz box from the origin with a hole of `radius` through its middle along Z,
// written to a temporary file named after `name` and the process; the caller removes it.
inline std::filesystem::path writeBoxWithHole(const std::string& name, double dx, double dy,
                                              double dz, double radius) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(dx, dy, dz).Shape();
    // Longer than the box at both ends, so that the cut leaves no skin.
    const TopoDS_Shape pin =
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(dx / 2, dy / 2, -1), gp_Dir(0, 0, 1)), radius,
                                 dz + 2)
            .Shape();
    BRepAlgoAPI_Cut cut(box, pin);
    if (!cut.IsDone()) return {};
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("idview_" + name + "_" + std::to_string(::getpid()) + ".brep");
    if (!BRepTools::Write(cut.Shape(), path.c_str())) return {};
    return path;
}

// This process's scratch folder for `name` (idview_NAME_PID in the temporary folder), made on
// first use and removed with everything in it when the process ends.
inline std::filesystem::path scratchFolder(const std::string& name) {
    struct Made {
        std::vector<std::filesystem::path> folders;
        ~Made() {
            std::error_code ignored;
            for (const std::filesystem::path& folder : folders)
                std::filesystem::remove_all(folder, ignored);
        }
    };
    static Made made;
    const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                         ("idview_" + name + "_" + std::to_string(::getpid()));
    if (std::filesystem::create_directories(folder)) made.folders.push_back(folder);
    return folder;
}

// XDG_CACHE_HOME is `folder` while this lives; its old value (or none) afterwards.
class CacheHome {
  public:
    explicit CacheHome(const std::filesystem::path& folder) {
        if (const char* old = std::getenv("XDG_CACHE_HOME")) saved_ = old;
        setenv("XDG_CACHE_HOME", folder.c_str(), 1);
    }
    ~CacheHome() {
        if (saved_)
            setenv("XDG_CACHE_HOME", saved_->c_str(), 1);
        else
            unsetenv("XDG_CACHE_HOME");
    }
    CacheHome(const CacheHome&) = delete;
    CacheHome& operator=(const CacheHome&) = delete;

  private:
    std::optional<std::string> saved_;
};

} // namespace cadtest
