// A fresh folder under the system temporary folder for one test, removed with its content.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace hrsr::testing {

class TempFolder {
public:
    TempFolder() {
        static int counter = 0;
        std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        for (char& c : test)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        path_ =
            std::filesystem::temp_directory_path() / ("hrsr_test_" + std::to_string(getpid()) +
                                                      "_" + test + "_" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;

    const std::filesystem::path& root() const { return path_; }
    std::string path(const std::string& file) const { return (path_ / file).string(); }
    /// Writes `bytes` to `file` in the folder and returns its path.
    std::string write(const std::string& file, const std::string& bytes) const {
        std::ofstream(path(file), std::ios::binary) << bytes;
        return path(file);
    }
    /// Names of the files in the folder, sorted (to check that nothing stray is left).
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::directory_iterator(path_))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    std::filesystem::path path_;
};

} // namespace hrsr::testing
