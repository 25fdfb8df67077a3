#pragma once
// The validated contents of one case file (docs/case-format.md). Everything here is physics or
// a numerical choice a reference code can also make; solver internals stay out. Built only by
// load_case(), so every field has passed its range checks.
#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <limits>
#include <string>
#include <vector>

#include "silodem/core/types.hpp"
#include "silodem/motion/motion_law.hpp"

namespace silodem {

/// Per-ball constants of one material, after derivation (contact/pair_constants.hpp).
struct Material {
  std::string name;
  double density = 0.0;  // kg/m³
  double k = 0.0;        // per-ball stiffness k_i, N/m (pairs combine in series, (11))
  double c = 0.0;        // per-ball viscosity c_i, N s/m
  std::string derived_from;  // "stiffness+damping", "contact_time+restitution", ...
  // Friction and rotation (docs/case-format.md "Friction"; pairs combine by docs/model.md §10.4).
  double friction = 0.0;                  // μ, Coulomb coefficient
  double rolling_friction = 0.0;          // μ_r, dimensionless (torque μ_r R* F_n)
  double rolling_damping_ratio = 0.0;     // η_r of the EPSD rolling dashpot C_r = 2 η_r √(I_r k_r)
  double shear_stiffness_ratio = 2.0 / 7.0;  // k_t,i / k_i of the linear history spring
  double tangential_damping_ratio = 0.0;  // γ_t,i / c_i (history spring), dimensionless
  double tangential_damping = 0.0;        // γ_t,i of the sliding law, N s/m
  // Hertz normal law (contact.normal "hertz"): elastic constants and the damping ratio ζ of
  // c = 2ζ√(m* S_n) that gives the material's restitution (docs/model.md §10.3).
  double youngs_modulus = 0.0;            // E, Pa
  double poisson_ratio = 0.0;             // ν
  double hertz_damping_ratio = 0.0;       // ζ
};

/// One grain–grain or grain–wall combination whose constants the case gives itself instead of
/// combining the two materials' (docs/case-format.md "material_pairs"); each absent one is combined.
struct MaterialPairSpec {
  std::string a, b;
  std::optional<double> friction, rolling_friction;
  std::optional<double> shear_stiffness_ratio, tangential_damping_ratio;  // history laws: k_t/k_n, γ_t/c_n
  std::optional<double> tangential_damping;   // sliding law: γ_t of the pair itself, N s/m
  std::optional<double> hertz_damping_ratio;  // Hertz: ζ of the pair, from its own restitution or damping_ratio
};

/// A slot across a tray's floor (at namespace scope: clang rejects a nested type's default member
/// initialisers inside its enclosing class).
struct TraySlot {
  double x = 0.0, width = 0.0;  // centre along x from the tray's centre, and the clear gap, m
};

struct WallSpec {
  std::string name;            // ball ids are <name>_<n>
  std::string type;            // "cylinder", "disk", "cone", "tray", "drum"
  std::string material;
  double r_min = 0.0, r_max = 0.0;  // wall-ball radii, uniform (1)
  double spacing = 0.0;        // centre distance between neighbouring wall balls
  Vec3 centre = Vec3::Zero();  // axis point (x, y) and base height z
  double diameter = 0.0;       // cylinder: inner diameter; disk: outer diameter; cone: top diameter
  double height = 0.0;         // cylinder: height above centre.z; cone: height below centre.z
  double hole_diameter = 0.0;  // disk: outlet hole; cone: outlet (bottom) diameter
  // tray (seed 001): a floor of `length` along x with side walls of `height`, centred on centre;
  // `depth` along y (0: one row in the plane y = centre.y, for the planar mode); slots across it.
  double length = 0.0, depth = 0.0;  // tray: length along x; drum: length along its axis (y)
  std::vector<TraySlot> slots;
  // drum (seed 003): a polygon of `sides` faces inside `diameter` about the axis along y through
  // centre, `length` along it (0: one ring in the plane y = centre.y), with lifters on face middles.
  int sides = 0, lifters = 0;
  double lifter_height = 0.0;
  std::optional<MotionLaw> motion;  // a wall in prescribed motion (motion/motion_law.hpp)
};

/// A smooth wall (scene/surface.hpp): the surface one straight segment of a meridian profile sweeps
/// turning about a vertical axis — a cylinder, a cone, an annulus or a disk. A case's profile is a
/// polyline; each of its segments is one SurfaceSpec with its own contact history.
struct SurfaceSpec {
  std::string name;                // the case's name, "_<k>" added for segment k of a longer profile
  std::string material;
  Vec3 axis_point = Vec3::Zero();     // a point of the axis, m (z = 0 for a vertical one given as [x, y])
  Vec3 axis_direction = Vec3::UnitZ();  // unit; vertical unless the case gives a direction
  double angular_speed = 0.0;         // spin about the axis, rad/s, right-handed (0: at rest)
  bool vertical() const { return axis_direction == Vec3::UnitZ(); }
  double rho0 = 0.0, z0 = 0.0;     // first end: distance from the axis and height, m
  double rho1 = 0.0, z1 = 0.0;     // second end
};

/// Whether a surface segment's name belongs to the case's surface `name` ("name" itself, or
/// "name_<k>" for segment k of a longer profile).
inline bool surface_of(const std::string& segment, const std::string& name) {
  if (segment == name) return true;
  if (segment.size() <= name.size() + 1 || segment.compare(0, name.size() + 1, name + "_") != 0) return false;
  return segment.find_first_not_of("0123456789", name.size() + 1) == std::string::npos;
}

struct BallSpec {
  std::string id;
  std::string material;
  double radius = 0.0;
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();  // rad/s, only in a scene whose balls rotate
  bool fixed = false;  // a wall ball: never integrated, its contact forces are the wall load
};

/// Filling by analytic free fall (Algorithm 2).
struct DropSpec {
  std::string material;
  double r_min = 0.0, r_max = 0.0;                  // radii uniform on [r_min, r_max] (1)
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;  // inlet rectangle (14)
  double z0 = 0.0;                                  // release height of the centre
  long count = 0;                                   // balls to place
  bool free_fall_velocity = true;                   // (16) √(2|g|h); false: the paper's zero option
  std::vector<std::array<double, 2>> positions;     // explicit (x0, y0) instead of random
  long interval_steps = 1;                          // at most one drop per this many steps
  // Placement "release": the ball starts at its release point (x0, y0, z0), moving down at
  // release_speed, and the integrator lets it fall — attempt k at step k·interval_steps,
  // whatever the fill. The
  // sequence (steps, points, radii) is fixed by the seed, so every code can replay it: the
  // shared fill protocol of the cross-code comparison (a). Default: Algorithm 2's first contact.
  bool release = false;
  double release_speed = 0.0;  // release: initial downward speed, m/s (clears the point sooner)
  // "Until the silo is full" (docs/model.md §4.2): the fill ends once the fill height (the median column
  // top over the inlet, DropFeeder::surface_height) reaches this level, even if count is not reached (count is then an upper bound). NaN: by count only.
  double full_level = std::numeric_limits<double>::quiet_NaN();
};

enum class Scheme { PredictorCorrector, VelocityVerlet, RungeKuttaMidpoint };
// FixedPoint: max|Δü⁽ʲ⁾ − Δü⁽ʲ⁻¹⁾| < ε_ü; PaperLiteral: the 2002 paper's (26) max|Δü⁽ʲ⁾| < ε_ü;
// Relative: seed 003's (31), |ü⁽ʲ⁾ − ü⁽ʲ⁻¹⁾| / |ü⁽ʲ⁾| < ε_a for every ball (and ω̇ likewise).
enum class CorrectorStop { FixedPoint, PaperLiteral, Relative };

struct IntegratorSpec {
  Scheme scheme = Scheme::PredictorCorrector;
  int max_corrector_passes = 1;                     // 1 = the paper's explicit form
  CorrectorStop corrector_stop = CorrectorStop::FixedPoint;
  double p_acc = 0.1;                               // ε_ü = p_ü |g| (26)
  double relative_tolerance = 1e-5;                 // ε_a of the relative stop (seed 003's (31) and its code)
  bool half_step_dashpot = false;                   // velocity Verlet: LAMMPS's lagged dashpot velocity
  double viscosity = 0.0;                           // midpoint RK2: seed 001's artificial viscosity μ, 1/s
};

/// What a case gets when it names no scheme or no step: the cheapest point of the work–precision
/// Pareto front that meets the documented accuracy (reports/work_precision.md, tools/work_precision.py:
/// restitution within 2 % for ζ ≤ 0.3 with the plain law, energy-ledger drift within 1 % on a
/// dense settling run).
inline constexpr Scheme kDefaultScheme = Scheme::VelocityVerlet;
inline constexpr double kDefaultDtPerContactTime = 1.0 / 50.0;
/// Steps between renumberings of the mobile balls in space (neighbour/spatial_order.hpp).
/// LAMMPS's `atom_modify sort` default is 1000 too; the sort costs about one step's time.
inline constexpr long kDefaultSortIntervalSteps = 1000;

/// Which stop test decides "at rest" (docs/case-format.md, `equilibrium`).
enum class EquilibriumTest {
  ForcesAndKinetic,  // (27)–(29) and E_kin < p_k E_el: the default
  PaperLiteral,      // (27)–(29) alone, as the paper prints them
};

struct EquilibriumSpec {  // (27)–(29), and the kinetic test beside them
  bool enabled = false;
  EquilibriumTest test = EquilibriumTest::ForcesAndKinetic;
  double p_f = 0.1;
  double p_ft = 0.01;
  double p_k = 1e-3;      // kinetic test: E_kin < p_k · E_el
  long check_interval_steps = 1;
  double min_time = 0.0;
};

/// The contact sub-models (docs/model.md §10), chosen once per scene.
enum class NormalModel { Linear, Hertz };
enum class TangentialModel { None, CoulombSliding, LinearHistory, Mindlin };
enum class RollingModel { None, ConstantTorque, Spring };  // Spring: EPSD (docs/model.md §10.5)

struct ContactSpec {
  NormalModel normal = NormalModel::Linear;
  TangentialModel tangential = TangentialModel::None;
  RollingModel rolling = RollingModel::None;
  std::vector<MaterialPairSpec> material_pairs;
  /// Balls carry angular velocity and torque: a tangential or rolling law is on.
  bool rotation() const { return tangential != TangentialModel::None || rolling != RollingModel::None; }
  /// The paper's law alone: the frictionless force loop of forces/force_field.cpp.
  bool frictionless_linear() const { return normal == NormalModel::Linear && !rotation(); }
  bool clamp = false;      // clamp the overlap force at zero (YADE, LAMMPS limit_damping)
  bool cohesion = false;   // Hookean cohesion zone (9)(10)
  double p_n = 0.1;        // p_N of (10)
  // Second-order contact onset and release (issue 5): the dashpot force jumps at first touch (and,
  // unclamped, at separation) between two steps; the trapezoid impulse of every scheme here then
  // errs by O(ζ ω Δt). Scaling the dashpot in that one step restores the impulse (force_field.cpp).
  bool onset_correction = false;
  /// Lever arm of the slip velocity: r − δ/2 to the contact point (default), or the radius r as
  /// LAMMPS 29Sep2021 `pair granular` takes it (contact.slip_lever_arm "radius"; torques keep r − δ/2).
  bool slip_arm_radius = false;
  /// The EPSD rolling limit: on the spring alone, the dashpot dropped at the limit (default; Ai et al.
  /// 2011, LIGGGHTS `epsd`), or on spring and dashpot together, as LAMMPS 29Sep2021 `rolling sds`
  /// (contact.rolling_limit "spring_and_dashpot").
  bool rolling_limit_with_dashpot = false;
};

/// Stages of a silo run (docs/model.md §7): what leaves through the outlet, and timed events.
struct OutflowSpec {
  bool enabled = false;
  double below_z = 0.0;   // a mobile ball whose centre falls below this height has left the silo
  bool recycle = true;    // the paper refills with the balls that left; false: they are removed
  long every_steps = 1;   // looked for at the top of every step s with s % every_steps == 0
};
struct StageEvent {
  double time = 0.0;
  std::string type;       // "open_outlet": the balls of `wall` are taken away or set free (discharge);
                          // "close_outlet": mobile balls in the outlet slab are stopped and fixed;
                          // "move_wall": the balls of `wall` (or the listed fixed ball `ball`) move
                          // at `velocity` from then on
  std::string wall;
  bool release_mobile = false;  // open_outlet: true = the gate balls become mobile (the paper's words);
                                // false = they are taken away (wall balls overlap by design, so set
                                // free they fly apart with the energy of those overlaps)
  Vec3 centre = Vec3::Zero();
  double diameter = 0.0, thickness = 0.0;
  std::string ball;              // move_wall: a listed fixed ball instead of a wall
  Vec3 velocity = Vec3::Zero();  // move_wall, m/s (zero stops the wall)
  /// Whether the wall ball with this id is one this event names (its wall's prefix, or its id).
  bool names(const std::string& id) const {
    return ball.empty() ? id.rfind(wall + "_", 0) == 0 : id == ball;
  }
};

struct ProbeSpec {
  std::string type;                // "pair", "ball", "drops", "wall_pressure", "wall_load", "outflow", "section_force", "velocity_field", "charge", "area_fraction"
  std::string name;
  std::vector<std::string> balls;  // ids
  // wall_pressure, wall_load, charge: which wall; the bins of its nominal surface, and when averaging starts
  std::string wall;
  int angle_bins = 12, height_bins = 10;
  double from_time = 0.0;
  double to_time = 0.0;            // > 0: the time average ends here (e.g. the filled state before discharge)
  double history_interval = 0.0;   // > 0: also a time series of the band-averaged pressure
  // section_force: the plane z = plane_z, a row every `interval` s from `from_time`
  double plane_z = 0.0;
  double interval = 0.0;           // also velocity_field's sampling period, wall_load's row period
  // velocity_field: rings about the vertical axis through field_centre, r < field_radius,
  // field_z[0] <= z < field_z[1], in radial_bins x height_bins cells
  Vec3 field_centre = Vec3::Zero();
  double field_radius = 0.0;
  double field_z[2] = {0.0, 0.0};
  double field_x[2] = {0.0, 0.0};  // area_fraction: x_low <= x < x_high (its cells: radial_bins along x)
  int radial_bins = 10;
};

/// Run guards (run/guards.hpp): cheap checks every step that stop a run which has gone wrong.
struct GuardSpec {
  double max_overlap_ratio = 0.5;  // δ / min(r_i, r_j) of any pair
  double max_travel_ratio = 0.5;   // |v| Δt / (smallest radius of the scene) of any mobile ball
  double max_energy_drift = 0.5;   // |ledger balance| / energy moved (energy is being created)
  double domain_margin = 1.0;      // m beyond the bounding box of the initial balls and drop points
  long max_steps = 0;              // 0: no limit beyond the duration
  double max_wall_seconds = 0.0;   // 0: no wall-clock limit
};

/// Periodic checkpoints (checkpoint/, `run --restart`): every `interval_steps` steps and/or every
/// `interval_seconds` of wall clock, whichever comes first; the newest `keep` are kept.
struct CheckpointSpec {
  long interval_steps = 0;         // 0: not by steps
  double interval_seconds = 0.0;   // 0: not by the clock
  int keep = 2;
  bool enabled() const { return interval_steps > 0 || interval_seconds > 0.0; }
};

/// Breakage (seed 003's population-balance replacement, docs/model.md §14): a grain of a breakable
/// material breaks into equal fragments once the elastic energy of its ended contacts, less
/// `minimum_energy` each, reaches its toughness, an exponential variate of rate `strength` drawn
/// once per grain from the seed (notes B7).
struct BreakageSpec {
  std::vector<std::string> materials;  // the breakable materials (ore); fragments keep theirs
  double minimum_energy = 0.0;         // E_min, J: only a contact's energy beyond it counts (34)
  double size_exponent = 0.0;          // E_min scales as (r/r_original)^this (0: constant, the text; 1: the code)
  double strength = 0.0;               // S, 1/J: P(broken | E_cum) = 1 − exp(−S E_cum) (36)
  double smallest_ratio = 0.5;         // a fragment with r < this × its original radius breaks no more
  double count_mean = 4.0, count_sd = 2.0 / 3.0;  // fragments: round(N(mean, sd)) clipped to [min, max]
  int count_min = 2, count_max = 6;
  bool secant_energy = false;          // literal: E = ½ k_sec δ_max² = 1.25 × the Hertz energy (notes B8)
  bool wall_contacts = true;           // contacts with wall balls count (the text; the code: false)
  double from_time = 0.0;              // s: contacts that end before it count nothing (a charge settling)
};

struct CaseConfig {
  std::string name;
  std::string description;
  std::uint64_t seed = 1;
  Vec3 gravity{0.0, 0.0, -9.81};   // z up (docs/model.md §1 Reading)
  int dimension = 3;               // 2: the planar mode, grains in the x–z plane spinning about y (model.md §13)
  double inertia_factor = 0.4;     // κ = I/(m r²) of a grain: 2/5 a solid sphere, 1/2 a disc (planar only)
  std::map<std::string, Material> materials;
  ContactSpec contact;
  std::vector<BallSpec> balls;              // listed balls, then the balls of each wall (ids <wall>_<n>), then the generated grains
  std::size_t listed_balls = 0;             // of them listed in "balls" or read from its state file
  std::size_t generated_balls = 0;          // of them made by "generate" (the last ones)
  std::vector<WallSpec> walls;              // walls built from "walls" (scene/wall_builders.hpp)
  std::vector<SurfaceSpec> surfaces;        // smooth walls, one per profile segment ("surfaces")
  std::optional<DropSpec> drops;
  std::optional<BreakageSpec> breakage;
  OutflowSpec outflow;
  std::vector<StageEvent> events;
  IntegratorSpec integrator;
  double dt = 0.0;                 // s (resolved from dt_per_contact_time if given so)
  std::optional<double> dt_per_contact_time;
  double duration = 0.0;           // s, the longest the run may go (end time, counted from t = 0)
  long start_step = 0;             // a continuation (output/state_file.hpp) starts at t = start_step · dt
  // A continuation's balls are where the run left them: the balls of walls in prescribed motion keep
  // their places at the law's origin here, by id (empty: the case's own wall balls are those places).
  std::vector<std::pair<std::string, Vec3>> wall_reference;
  EquilibriumSpec equilibrium;
  GuardSpec guards;
  CheckpointSpec checkpoint;
  double skin = 0.0;               // neighbour-list skin, m (0: chosen from the radii)
  long sort_interval_steps = kDefaultSortIntervalSteps;  // renumbering of the mobile balls in space (0: never)
  double series_interval = 0.0;    // s between time-series rows (0: every step)
  long dump_interval_steps = 0;    // particle dumps every this many steps (0: none)
  bool state_json = true;          // state.json beside state.sds (output/state_file.hpp)
  long vtk_interval_steps = 0;     // VTK snapshots (output/vtk_writer.hpp) every this many steps (0: none)
  bool vtk_float64 = false;        // VTK reals in Float64 (output.vtk_precision "float64") rather than Float32
  std::vector<ProbeSpec> probes;
  nlohmann::json verify;           // checks for `silodem verify`, read by the harness
  nlohmann::json source;           // the case as given, echoed into the summary
};

}  // namespace silodem
