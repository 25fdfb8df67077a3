#pragma once
// A smooth wall (docs/model.md §11) as triangles, for the codes whose walls are meshes.
#include <string>

#include "silodem/case/case_config.hpp"

namespace harness {

/// The codes' meshes of a smooth wall: 720 facets around (0.5 degrees apart), triangles at most 20
/// times longer than wide (angles above 2.8 degrees).
inline constexpr int kMeshSegments = 720;
inline constexpr double kMeshAspect = 20.0;

/// The surface of revolution as an ASCII STL of `segments` quads around the axis (two triangles
/// each), in rows along the profile so that no triangle is more than `max_aspect` times longer
/// than its width (LIGGGHTS refuses a mesh whose triangles have an angle below its `curvature`).
/// The ring vertices lie at ρ (π/N)/sin(π/N), so each facet's mean distance from the axis is
/// the surface's ρ: the polygon lies within ρ (π/N)²/3 inside the circle (the flats' middle) and
/// ρ (π/N)²/6 outside it (the vertices): 0.6 and 0.3 µm at ρ = 0.1 m, N = 720, against the grains'
/// overlaps of microns. Flat rings (ρ from 0) are refused by the backends that call this.
std::string surface_stl(const silodem::SurfaceSpec& s, int segments, double max_aspect);

}  // namespace harness
