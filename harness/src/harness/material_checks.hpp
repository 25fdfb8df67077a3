#pragma once
// Virtual material tests (EN 1991-4 Annex C on the silo's own grains and wall): the parameters a
// silo engineer measures and the Janssen prediction takes. Each gives a measured value — a report
// row, there is no oracle — and the spread check (across_variants.cpp) its scatter over packings.
#include <nlohmann/json.hpp>

#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// A column of grains in a cylinder wall, as a wall_pressure probe of the cylinder and the run's
/// fill see it: the wall's geometry, the column's floor and top, and its bulk unit weight.
struct ColumnInWall {
  CsvTable probe;
  double D = 0.0, H = 0.0;   // the cylinder's diameter and height
  double z_base = 0.0;       // the cylinder's base (band h spans z_base + H [h, h + 1]/bins)
  double z_floor = 0.0;      // where the column stands (checks.hpp column_floor)
  double z_top = 0.0, mass = 0.0, area = 0.0;
  double gamma = 0.0;        // bulk unit weight: the column's weight over its volume
  double band_mid(int h, int bins) const { return z_base + H * (h + 0.5) / bins; }
};
ColumnInWall column_in_wall(const std::string& probe, const RunContext& ctx);

/// Both checks below read {"wall_probe": name, "exclude_bottom_diameters": 0.5, "exclude_top_diameters": 0.5}:
/// the wall_pressure probe of a cylinder and the bands of the column between the excluded ends.
void validate_mantle_band_check(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);

/// "lateral_pressure_ratio": a column at rest against a frictionless wall, K = σ_h/σ_v per band of
/// the mantle with σ_v from the slice equilibrium (docs/theory.md §4.1).
std::vector<CheckRow> lateral_pressure_ratio(const nlohmann::json& spec, const RunContext& ctx);

/// "wall_friction": the mantle sliding past a column at rest, μ_w = Σ τ / Σ p of the probe's time
/// means over the column's bands (docs/theory.md §4.2).
std::vector<CheckRow> wall_friction(const nlohmann::json& spec, const RunContext& ctx);

/// "direct_shear": {"section_probe": a section_force probe on the plane between the rings,
/// "moving_wall": the ring a move_wall event drives sideways, "smoothing": running-mean travel (m),
/// "critical_from": the fraction of the travel after which the stress ratio is the critical state's}.
void validate_direct_shear(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);

/// The shear box: τ/σ across the plane along the ring's travel; the peak and the critical-state
/// angles of internal friction (docs/theory.md §4.4).
std::vector<CheckRow> direct_shear(const nlohmann::json& spec, const RunContext& ctx);

}  // namespace harness
