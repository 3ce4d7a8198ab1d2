// Files for the experiment tests (study_experiment_test): the shipped experiments' folder, a
// fresh folder under the build tree, a file read whole.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace ps::study::test_files {

inline const std::string kStudies = std::string(PS_SOURCE_DIR) + "/scenes/studies/";

// build/tests/study/GROUP/NAME, emptied.
inline std::string fresh_dir(const std::string& group, const std::string& name) {
  const std::string dir = std::string(PS_BINARY_DIR) + "/tests/study/" + group + "/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace ps::study::test_files
