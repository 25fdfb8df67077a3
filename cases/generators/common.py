"""Pieces the case generators share: the integrator and contact-end variant axes (JSON merge
patches, so null removes a key the base case set) and the scheme every reference code runs."""
import json
import math

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
    """The case as indented JSON, but each listed ball on one line (a scene of 28,000 balls stays
    under 2 MB); the values are those json.dump writes either way."""
    balls = case.get("balls")
    if not balls:
        text = json.dumps(case, indent=1)
    else:
        marker = "\u0000balls\u0000"
        text = json.dumps(dict(case, balls=marker), indent=1)
        listed = ",\n".join("  " + json.dumps(b, separators=(",", ":")) for b in balls)
        text = text.replace(json.dumps(marker), "[\n" + listed + "\n ]")
    with open(path, "w") as f:
        f.write(text + "\n")


# The final ledgers across codes, as fractions of the energy moved (check "energy_terms"):
# compared as plain differences of those fractions.
ENERGY_BETWEEN = [{"quantity": q, "tolerance": 0.05, "relative_to": "absolute"}
                  for q in ("energy_kinetic", "energy_elastic", "energy_gravitational_change", "energy_lost")]

# Where a tolerance comes from (docs/case-format.md, "Tolerance sources"); without one its rows
# are reported, not judged.
# Every reference code integrates the same scheme as silodem in these comparisons.
SAME_SCHEME = {"type": "scheme_bound", "derivation":
               "every code integrates the same scheme (velocity Verlet, dashpot at the half-step velocity) from the "
               "same state, so they differ by floating-point rounding only (at most 3e-12 measured, "
               "reports/comparison.md); 1e-5 is far above that and far below the change a contact seen one step "
               "earlier or later makes (at least Omega^2/8 = 5e-4 at t_c/dt = 50, references/restitution.hpp)"}

# The seed scatter of silodem's own realisations (compare "seeds"), measured by the clean-clone run
# of reports/tables/checks_compare.csv (commit cae5c1f, rows "silodem seeds": the sample standard
# deviation over seeds 2002, 2003, 2004 on each between_codes row's scale; profiles: the worst band).
SCATTER_MEASURED = "reports/tables/checks_compare.csv at cae5c1f, rows 'silodem seeds', seeds 2002-2004"


def with_scatter(entry, scatter):
    """The between_codes entry with the measured seed scatter as its tolerance's source, if the
    tolerance is at most 10 scatters; a looser tolerance is not made by the scatter and stays
    without a source, so its rows are reported (as is a quantity with no scatter: 0 by construction)."""
    if scatter and entry["tolerance"] <= 10 * scatter:
        return dict(entry, tolerance_source={"type": "seed_scatter", "realisations": 3, "scatter": scatter,
                                             "measured": SCATTER_MEASURED})
    return entry


def without_scatter_sources(between):
    """The entries without seed-scatter sources: the scatter was measured at CI size, not for
    another size (paper) or without seeds."""
    return [{k: v for k, v in e.items() if not (k == "tolerance_source" and v["type"] == "seed_scatter")}
            for e in between]


def energy_between(scatter, relative_lost=False):
    """ENERGY_BETWEEN with the case's measured scatter per quantity (energy_lost relative to itself
    when `relative_lost`)."""
    out = []
    for e in ENERGY_BETWEEN:
        if relative_lost and e["quantity"] == "energy_lost":
            e = dict(e, relative_to="value")
        out.append(with_scatter(e, scatter.get(e["quantity"], 0.0)))
    return out


def between_from_scatter(quantity, scatter, realisations, measured, **keys):
    """A between_codes entry judged against the measured seed scatter: two codes continuing one
    state are two realisations of the same chaotic flow, so their difference has the standard
    deviation sqrt(2) x scatter; the tolerance is twice that (coverage 2)."""
    tolerance = round(2.0 * math.sqrt(2.0) * scatter, 4)
    return dict({"quantity": quantity, "tolerance": tolerance}, **keys,
                tolerance_source={"type": "seed_scatter", "realisations": realisations, "scatter": scatter,
                                  "measured": measured})


def between_mean_from_scatter(quantity, scatter, realisations, mean_of, measured, **keys):
    """A between_codes entry for a time mean over a chaotic flow, judged against the mean of
    silodem's mean_of realisations (its run and one per compare seed, "silodem_value": "seeds_mean"):
    a code's run and that mean differ with the standard deviation sqrt(1 + 1/mean_of) x scatter
    (the scatter measured over `realisations`); the tolerance is twice that (coverage 2)."""
    tolerance = round(2.0 * math.sqrt(1.0 + 1.0 / mean_of) * scatter, 4)
    return dict({"quantity": quantity, "tolerance": tolerance, "silodem_value": "seeds_mean"}, **keys,
                tolerance_source={"type": "seed_scatter", "realisations": realisations, "scatter": scatter,
                                  "measured": measured})


def as_speed_run(case, scale, description, quantity):
    """A generator's case at `scale` times its size, for the speed runs: its own name and
    description, and the between-codes rows of `quantity` reported, since the seed scatter that
    judges them was measured at scale 1."""
    case["name"] = "%s_x%d" % (case["name"], scale)
    case["description"] = description
    case["compare"]["between_codes"] = [{"quantity": quantity, "report": "a speed run's larger size: the seed scatter "
                                         "that judges it was measured at scale 1"}]

