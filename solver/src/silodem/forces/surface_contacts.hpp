#pragma once
// Contacts of mobile balls with the smooth walls of a scene (scene/surface.hpp, docs/model.md §11):
// each ball against each surface through the same contact sub-models as a pair of balls
// (contact/contact_model.hpp), the wall a partner of infinite radius and mass, at rest or spinning
// about its own axis.
// Runs after the pair loop and adds to the forces and torques it left.
#include <memory>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/scene/particles.hpp"
#include "silodem/scene/surface.hpp"

namespace silodem {

class Archive;

class SurfaceContacts {
 public:
  virtual ~SurfaceContacts() = default;
  /// Adds every ball–surface contact force and torque to p.f, p.t at the current (x, v, ω) and
  /// returns their energy terms (to be added to the pair loop's).
  virtual ForceTotals compute(Particles& p) = 0;
  /// The step is accepted: the tangential and rolling springs move on (as ForceField::commit).
  virtual void commit() = 0;
  /// Checkpoint of the springs, by ball tag.
  virtual void serialize(Archive& a) = 0;
  virtual std::size_t bytes() const = 0;
  /// The force the balls put on each surface at the last evaluation (its load), N, by surface.
  virtual const std::vector<Vec3>& loads() const = 0;
  /// The torque the balls put on each surface about its axis point c, N m: Σ (x_c − c) × f_wall
  /// plus the reactions of the rolling torques.
  virtual const std::vector<Vec3>& torques() const = 0;
  /// The spinning surfaces' power into the balls at the last evaluation, W: −Σ_k Ω_k a_k · T_k.
  virtual double power() const = 0;
  /// Whether any surface spins (its work then enters the energy ledger).
  bool spinning() const {
    for (const Surface& s : surfaces())
      if (s.angular_speed != 0.0) return true;
    return false;
  }
  virtual const std::vector<Surface>& surfaces() const = 0;
};

/// The scene's smooth walls with the case's contact law; null when the case has none.
/// `material_names`: the scene's material order (Particles::material indexes it).
std::unique_ptr<SurfaceContacts> make_surface_contacts(const CaseConfig& cfg,
                                                       const std::vector<std::string>& material_names);

/// Adds b's terms to a (the maximum overlap ratio taken as the larger).
void add_totals(ForceTotals& a, const ForceTotals& b);

}  // namespace silodem
