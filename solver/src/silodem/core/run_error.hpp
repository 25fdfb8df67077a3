#pragma once
#include <stdexcept>

namespace silodem {

/// A run that could not continue (non-finite state, a guard tripped, ...): exit code 3, distinct
/// from bad input (2). Thrown from wherever the run finds out, the run loop included.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace silodem
