#pragma once
#include <string>

namespace silodem {

/// Stops the whole command, not just one run: a result cannot be written, an output path is
/// refused, a signal arrived. Deliberately not a std::exception, so that no harness loop that
/// turns a failed run into a failed row can swallow it; main prints it and exits with its code.
class JobStop {
 public:
  JobStop(int exit_code, std::string message) : exit_code_(exit_code), message_(std::move(message)) {}
  virtual ~JobStop() = default;
  const char* what() const noexcept { return message_.c_str(); }
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
  std::string message_;
};

}  // namespace silodem
