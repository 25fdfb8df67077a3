// The malformed-case corpus (tests/solver/case/corpus/, listed with its expectations in
// expected.tsv): every bad file is refused with a CaseError that names the expected JSON path
// and says why; every valid file loads. The same files seed the loader's fuzz target (fuzz/).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kCorpus = fs::path(SILODEM_SOURCE_DIR) / "tests/solver/case/corpus";

struct Expectation {
  std::string file, path, message;  // path "FILE": the error names the file; "-": the case must load
};

std::vector<Expectation> expectations() {
  std::ifstream in(kCorpus / "expected.tsv");
  std::vector<Expectation> out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Expectation e;
    std::getline(fields, e.file, '\t');
    std::getline(fields, e.path, '\t');
    std::getline(fields, e.message);
    out.push_back(e);
  }
  return out;
}

}  // namespace

TEST(CaseCorpus, EveryFileIsListedAndTheCorpusIsLarge) {
  std::set<std::string> listed, on_disk;
  std::size_t bad = 0, good = 0;
  for (const auto& e : expectations()) {
    listed.insert(e.file);
    (e.path == "-" ? good : bad) += 1;
  }
  for (const auto& f : fs::directory_iterator(kCorpus))
    if (f.path().extension() == ".json") on_disk.insert(f.path().filename().string());
  EXPECT_EQ(listed, on_disk) << "expected.tsv and the corpus files differ";
  EXPECT_GE(bad, 50u);
  EXPECT_GE(good, 5u);
}

TEST(CaseCorpus, BadFilesAreRefusedNamingThePathAndTheReason) {
  for (const auto& e : expectations()) {
    if (e.path == "-") continue;
    SCOPED_TRACE(e.file);
    const fs::path file = kCorpus / e.file;
    const std::string want_path = e.path == "FILE" ? file.string() : e.path;
    try {
      silodem::load_case_file(file);
      ADD_FAILURE() << "accepted";
    } catch (const silodem::CaseError& err) {
      const std::string what = err.what();
      EXPECT_EQ(err.path(), want_path) << what;
      EXPECT_EQ(what.rfind(want_path + ": ", 0), 0u) << "the message must start with the path: " << what;
      EXPECT_NE(what.find(e.message), std::string::npos) << "expected \"" << e.message << "\" in: " << what;
    } catch (const std::exception& err) {
      ADD_FAILURE() << "not a CaseError (the CLI would report an internal error): " << err.what();
    }
  }
}

TEST(CaseCorpus, ValidFilesLoad) {
  for (const auto& e : expectations()) {
    if (e.path != "-") continue;
    SCOPED_TRACE(e.file);
    try {
      const auto cfg = silodem::load_case_file(kCorpus / e.file);
      EXPECT_GT(cfg.dt, 0.0);
    } catch (const std::exception& err) {
      ADD_FAILURE() << err.what();
    }
  }
}
