#pragma once
// The "surfaces" section of a case (docs/case-format.md "Smooth walls"): profiles turned about a
// vertical axis, each segment one smooth wall (scene/surface.hpp).
#include "silodem/case/case_config.hpp"
#include "silodem/case/json_reader.hpp"

namespace silodem::case_keys {

/// Reads every surface of r["surfaces"] into cfg.surfaces, one SurfaceSpec per profile segment.
void read_surfaces(const JsonReader& r, CaseConfig& cfg);

/// Refuses a listed mobile ball that starts deeper in a surface than the overlap guard allows:
/// the first step would fire it off the wall, or through it.
void check_surface_overlaps(const CaseConfig& cfg, const std::string& path);

}  // namespace silodem::case_keys
