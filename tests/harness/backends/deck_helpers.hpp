#pragma once
// What the backend tests share: a backend's generated input for a case, and lookups in it.
#include <stdexcept>
#include <string>

#include "harness/backends/reference_backend.hpp"
#include "harness/backends/translation.hpp"

namespace deck_helpers {

inline bool has(const std::string& text, const std::string& piece) { return text.find(piece) != std::string::npos; }

inline const std::string& file(const harness::ReferenceBackend::Input& in, const std::string& name) {
  for (const auto& [n, c] : in.files)
    if (n == name) return c;
  throw std::runtime_error("no file " + name);
}

/// The input a reference backend writes for the case (from its own translation, in its own axes).
inline harness::ReferenceBackend::Input input_of(const harness::Backend& backend, const silodem::CaseConfig& cfg) {
  std::string why;
  const auto& ref = dynamic_cast<const harness::ReferenceBackend&>(backend);
  return ref.write_input(cfg, ref.translation(cfg, why));
}

}  // namespace deck_helpers
