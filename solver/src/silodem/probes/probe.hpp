#pragma once
// A probe watches the run after every accepted step and writes what it saw as result files.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/fill/drop_feeder.hpp"
#include "silodem/run/stages.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class SurfaceContacts;

class Archive;

class Probe {
 public:
  explicit Probe(std::string name) : name_(std::move(name)) {}
  virtual ~Probe() = default;
  const std::string& name() const { return name_; }
  virtual void sample(const Particles& p, double t) = 0;
  virtual void on_drop(const DropRecord&) {}
  virtual void on_exit(const ExitRecord&) {}
  /// Checkpoint: what the probe has gathered so far (its caches of indices too: the topology
  /// counter they are keyed on is restored with the balls).
  virtual void serialize(Archive& a) = 0;
  /// Writes <dir>/<name>.csv; returns a digest for the summary.
  virtual nlohmann::json write(const std::filesystem::path& dir) const = 0;

 private:
  std::string name_;
};

/// `surfaces`: the scene's smooth walls (null without), for wall_load probes on them.
std::vector<std::unique_ptr<Probe>> make_probes(const CaseConfig& cfg, const SurfaceContacts* surfaces = nullptr);

}  // namespace silodem
