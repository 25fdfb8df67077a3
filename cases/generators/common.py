"""Pieces the case generators share: the integrator and contact-end variant axes (JSON merge
patches, so null removes a key the base case set) and the scheme every reference code runs."""
import json

_VV = {"scheme": "velocity_verlet", "max_corrector_passes": None, "corrector_stop": None}

INTEGRATORS = {
    "pc_explicit": {"integrator": {"scheme": "predictor_corrector", "max_corrector_passes": 1}},
    "pc_multi_fixed_point": {"integrator": {"scheme": "predictor_corrector", "max_corrector_passes": 10,
                                            "corrector_stop": "fixed_point"}},
    "pc_multi_literal26": {"integrator": {"scheme": "predictor_corrector", "max_corrector_passes": 10,
                                          "corrector_stop": "paper_literal"}},
    "velocity_verlet": {"integrator": dict(_VV)},
    # LAMMPS's form: theory uses the lagged-dashpot closed form (references/restitution.hpp).
    "velocity_verlet_half_step": {"integrator": dict(_VV, dashpot_velocity="half_step")},
}

CONTACT_END = {
    "unclamped": {"contact": {"clamp_tensile_force": False}},
    "clamped": {"contact": {"clamp_tensile_force": True}},
}

# LAMMPS/LIGGGHTS fix nve/sphere and YADE's leapfrog: velocity Verlet, dashpot at the half-step velocity.
REFERENCE_SCHEME = {"integrator": dict(_VV, dashpot_velocity="half_step")}


def integrators(*names):
    """The integrator axis restricted to `names` (all if none given)."""
    return {n: INTEGRATORS[n] for n in (names or INTEGRATORS)}


def write_case(case, path):
    with open(path, "w") as f:
        json.dump(case, f, indent=1)
        f.write("\n")


# The final ledgers across codes, as fractions of the energy moved (check "energy_terms"):
# compared as plain differences of those fractions.
ENERGY_BETWEEN = [{"quantity": q, "tolerance": 0.05, "relative_to": "absolute"}
                  for q in ("energy_kinetic", "energy_elastic", "energy_gravitational_change", "energy_lost")]
