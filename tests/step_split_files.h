// step_split_files.h - what the STEP splitter's tests share: a STEP file around a handmade
// DATA section, and text written to a temporary file that goes with the object.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace steptest {

// A complete STEP file whose DATA section holds `data`.
inline std::string stepFile(std::string_view data) {
    return std::string("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('handmade; DATA;'),'2;1');\n"
                       "FILE_NAME('t.step','2024-01-01T00:00:00',(''),(''),'','','');\n"
                       "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\n"
                       "ENDSEC;\nDATA;\n") +
           std::string(data) + "ENDSEC;\nEND-ISO-10303-21;\n";
}

// `text` written to a file of the temporary folder, named after `name` and the process;
// removed when this goes.
class TempFile {
  public:
    TempFile(const std::string& name, std::string_view text)
        : path_(std::filesystem::temp_directory_path() /
                ("idview_split_" + std::to_string(::getpid()) + "_" + name)) {
        std::ofstream(path_, std::ios::binary).write(text.data(), std::streamsize(text.size()));
    }
    ~TempFile() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    std::string path() const { return path_.string(); }

  private:
    std::filesystem::path path_;
};

} // namespace steptest
