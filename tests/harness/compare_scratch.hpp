#pragma once
// A scratch case (scratch_case.hpp) compared quietly in every code it names.
#include <filesystem>
#include <string>

#include "harness/compare.hpp"

namespace test_scratch {

/// `silodem compare` of DIR/FILE into DIR/OUT, without progress lines.
inline harness::VerifyOutcome compare_scratch(const std::filesystem::path& dir, const std::string& file, const std::string& out) {
  harness::CompareOptions opt;
  opt.out_root = dir / out;
  opt.progress = false;
  return harness::compare_cases({dir / file}, opt);
}

}  // namespace test_scratch
