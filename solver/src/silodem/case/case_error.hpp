#pragma once
// The one error type for bad input: it names the JSON path of the offending field, so a user
// can find it in the case file, and the CLI maps it to exit code 2.
#include <stdexcept>
#include <string>

namespace silodem {

class CaseError : public std::runtime_error {
 public:
  CaseError(std::string path, const std::string& reason)
      : std::runtime_error(path + ": " + reason), path_(std::move(path)) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace silodem
