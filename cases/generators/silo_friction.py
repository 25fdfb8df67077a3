"""The silo cases' frictional grains (silo_frictional.py's material): Coulomb friction mu = 0.5
between grains and 0.3 against the wall balls, a history spring with a tangential dashpot of half
the normal one's damping ratio; the grains, walls, stages and probes of the case stay as they are."""


def with_friction(case):
    """The case (modified in place and returned) with the silo's frictional material."""
    case["contact"] = {"tangential": "linear_history"}
    case["materials"]["grain"].update({"friction": 0.5, "tangential_damping_ratio": 0.5})
    case["materials"]["wall"].update({"friction": 0.0, "tangential_damping_ratio": 0.5})
    case["material_pairs"] = [{"materials": ["grain", "wall"], "friction": 0.3}]
    return case
