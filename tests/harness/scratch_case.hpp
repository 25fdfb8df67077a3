#pragma once
// A test's own scratch folder under the temporary directory, emptied first (a leftover of an
// earlier run is the test's, not silodem's output), holding one case file.
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace test_scratch {

/// TMP/<name>, emptied, with `case_json` written to it as `file`; returns the folder.
inline std::filesystem::path with_case(const std::string& name, const std::string& file, const nlohmann::json& case_json) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / file) << case_json.dump();
  return dir;
}

}  // namespace test_scratch
