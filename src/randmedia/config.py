"""Validation of the study configuration before any job runs.

:func:`validate_config` checks the merged Snakemake config against the JSON
schema ``workflow/schemas/config.schema.yaml`` (filling the schema's
defaults in place) and then the constraints that relate several keys, which a
schema cannot express. Every problem is reported as one line naming the
config key (dotted path) and what was expected.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping, MutableMapping

import jsonschema
import yaml

from randmedia.numerics.gaussian import default_margin


class ConfigError(ValueError):
    """The configuration is invalid; the message names each offending key."""


def _with_default_filling(validator_class):
    """Extend a jsonschema validator so that ``default`` values are inserted (also the
    default of a property whose schema is a ``$ref`` to another file)."""
    validate_properties = validator_class.VALIDATORS["properties"]

    def set_defaults(validator, properties, instance, schema):
        if isinstance(instance, dict):
            for name, subschema in properties.items():
                if name in instance:
                    continue
                if "default" not in subschema and "$ref" in subschema:
                    subschema = validator._resolver.lookup(subschema["$ref"]).contents
                if "default" in subschema:
                    instance[name] = _copy(subschema["default"])
        yield from validate_properties(validator, properties, instance, schema)

    return jsonschema.validators.extend(validator_class, {"properties": set_defaults})


def _copy(value):
    return yaml.safe_load(yaml.safe_dump(value))


def merge_config(base: dict, override: dict) -> dict:
    """``base`` updated by ``override`` the way Snakemake merges ``--configfile`` files over
    the Snakefile's ``configfile``: mappings recursively, every other value (lists
    included) replaced. Returns a new dict; the inputs are not changed."""
    merged = _copy(base)
    for key, value in override.items():
        if isinstance(value, dict) and isinstance(merged.get(key), dict):
            merged[key] = merge_config(merged[key], value)
        else:
            merged[key] = _copy(value)
    return merged


def load_config(*paths: str | Path) -> dict:
    """The config Snakemake sees for ``--configfile`` files ``paths[1:]`` over ``paths[0]``
    (e.g. ``load_config("config/config.yaml", "config/quick.yaml")``), before validation."""
    merged: dict = {}
    for path in paths:
        with open(path) as handle:
            merged = merge_config(merged, yaml.safe_load(handle) or {})
    return merged


_Validator = _with_default_filling(jsonschema.Draft202012Validator)


def _dotted(path) -> str:
    return ".".join(str(p) for p in path) or "<top level>"


def _describe(error: jsonschema.ValidationError) -> str:
    """One line naming the offending key for a schema violation."""
    where = list(error.absolute_path)
    if error.validator == "required":
        missing = error.message.split("'")[1]
        return f"config key '{_dotted(where + [missing])}' is required but missing"
    if error.validator == "additionalProperties":
        allowed = sorted(error.schema.get("properties", {}))
        unknown = sorted(set(error.instance) - set(allowed))
        return "; ".join(
            f"config key '{_dotted(where + [name])}' is unknown (allowed here: {', '.join(allowed)})"
            for name in unknown
        )
    bounds = {"minimum": ">=", "exclusiveMinimum": ">", "maximum": "<=", "exclusiveMaximum": "<"}
    if error.validator in bounds:
        problem = f"must be {bounds[error.validator]} {error.validator_value}, got {error.instance!r}"
    elif error.validator == "type":
        problem = f"must be of type {error.validator_value}, got {error.instance!r}"
        if isinstance(error.instance, str) and _looks_numeric(error.instance):
            problem += (" (snakemake --config passes values nested in {...} as text; "
                        "put the change in a config file and add it with --configfile)")
    else:
        problem = error.message
    meaning = error.schema.get("description", "")
    hint = f" -- {meaning.split('. ')[0]}" if meaning and error.schema.get("type") != "object" else ""
    return f"config key '{_dotted(where)}' {problem}{hint}"


def _looks_numeric(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _cross_checks(config: dict) -> list[str]:
    """Constraints between keys; run only on a schema-valid config. One function per
    config section (:data:`CROSS_CHECKS`), each returning one line per problem."""
    problems = []
    for path, check in CROSS_CHECKS.items():
        section = config
        for key in path.split("."):
            section = section[key]
        problems += check(section, config)
    return problems


# --------------------------------------------------------------------------- debye2020


def _debye2020_checks(section: dict, config: dict) -> list[str]:
    """debye2020.media, .chords, .overlapping_disks, .interface, .fits: ranges that must fit
    the images and windows that must lie inside the computed ranges."""
    problems = []
    media = section["media"]
    for key in ("a", "lc"):
        if media[key] >= media["L"] / 2:
            problems.append(
                f"config key 'debye2020.media.{key}': {media[key]:g} must be < L/2 = "
                f"{media['L'] / 2:g} (beyond half the periodic image a distance is not unique)"
            )
    disks = section["overlapping_disks"]
    chords = section["chords"]
    for part, length_key in (("media", "a"), ("overlapping_disks", "radius")):
        values = section[part]
        z_max = chords["z_max_over_length"] * values[length_key]
        if z_max >= 4 * values["L"]:
            problems.append(
                "config key 'debye2020.chords.z_max_over_length': z_max = "
                f"{z_max:g} pixels for {part} must be shorter than the 4 L = "
                f"{4 * values['L']} pixel sampling lines"
            )
    side, radius = disks["L"], disks["radius"]
    r_max = disks["s2_r_max_over_R"] * radius
    if r_max >= side / 2:
        problems.append(
            "config key 'debye2020.overlapping_disks.radius': S2 is wanted out to "
            f"s2_r_max_over_R * radius = {r_max:g} pixels, which must be < L/2 = {side / 2:g} "
            "(beyond half the periodic image a distance is not unique); "
            "use a smaller radius or s2_r_max_over_R, or a larger L"
        )
    if r_max + 2 * radius > side:
        problems.append(
            "config key 'debye2020.overlapping_disks.radius': on the periodic image the exact "
            f"Eqs. (32)-(33) hold for r <= L - 2R; need s2_r_max_over_R * R + 2R = "
            f"{r_max + 2 * radius:g} <= L = {side}"
        )
    if disks["compare_r_max_over_R"] > disks["s2_r_max_over_R"]:
        problems.append(
            "config key 'debye2020.overlapping_disks.compare_r_max_over_R': "
            f"{disks['compare_r_max_over_R']:g} exceeds s2_r_max_over_R = "
            f"{disks['s2_r_max_over_R']:g} (cannot compare bins that are not computed)"
        )
    if not any(abs(disks["phi2"] - phi) < 1e-12 for phi in media["phi2"]):
        problems.append(
            f"config key 'debye2020.overlapping_disks.phi2': {disks['phi2']:g} must be one of "
            f"debye2020.media.phi2 {media['phi2']} (Sec. VI compares all models at one phi2, "
            "Figs. 9-12)"
        )
    interface = section["interface"]
    low, high = interface["sigma_bracket"]
    if not low < high:
        problems.append(
            "config key 'debye2020.interface.sigma_bracket': need [low, high] with low < high, "
            f"got {interface['sigma_bracket']}"
        )
    cells = interface["bin_width"] * interface["supersample"]
    if abs(cells - round(cells)) > 1e-9 or round(cells) < 1:
        problems.append(
            f"config key 'debye2020.interface.bin_width': {interface['bin_width']:g} pixels must be "
            f"a whole multiple of the sub-pixel 1/supersample = {1 / interface['supersample']:g}"
        )
    for part, length_key in (("media", "a"), ("overlapping_disks", "radius")):
        values = section[part]
        r_max = interface["r_max_over_length"] * values[length_key]
        if r_max >= values["L"] / 2:
            problems.append(
                "config key 'debye2020.interface.r_max_over_length': F_sv, F_ss are wanted out "
                f"to {r_max:g} pixels for {part}, which must be < L/2 = {values['L'] / 2:g}"
            )
    if interface["r_max_over_length"] * radius + 2 * radius > side:
        problems.append(
            "config key 'debye2020.interface.r_max_over_length': on the periodic image the exact "
            "Eqs. (35)-(36) hold for r <= L - 2R; need r_max_over_length * R + 2R <= L"
        )
    fits = section["fits"]
    for key in ("formula_r_max_over_a", "euler_fit_r_max_over_a", "euler_fit_r_max_alt_over_a"):
        if fits[key] > interface["r_max_over_length"]:
            problems.append(
                f"config key 'debye2020.fits.{key}': {fits[key]:g} exceeds "
                f"interface.r_max_over_length = {interface['r_max_over_length']:g} "
                "(F_sv is not computed that far)"
            )
    for key, r_min in (("formula_r_max_over_a", fits["formula_r_min"]),
                       ("euler_fit_r_max_over_a", fits["euler_fit_r_min"]),
                       ("euler_fit_r_max_alt_over_a", fits["euler_fit_r_min"])):
        if fits[key] * media["a"] <= r_min + 2 * interface["bin_width"]:
            problems.append(
                f"config key 'debye2020.fits.{key}': the window ends at {fits[key] * media['a']:g} "
                f"pixels, too close to its start {r_min:g} for a fit over radial bins of "
                f"{interface['bin_width']:g} pixels"
            )
    return problems


def _hard_particle_mc_checks(prefix: str, section: dict) -> list[str]:
    """Constraints inside the shared Monte Carlo settings (``<section>.mc``)."""
    mc = section["mc"]
    problems = []
    if mc["contact_bins"] < mc["contact_order"] + 2:
        problems.append(
            f"config key '{prefix}.mc.contact_bins': {mc['contact_bins']} bins cannot fit a "
            f"degree-{mc['contact_order']} polynomial with a residual (need >= contact_order + 2)")
    if section["n_chains"] * section["samples_per_chain"] < 2:
        problems.append(
            f"config key '{prefix}.samples_per_chain': n_chains x samples_per_chain = "
            f"{section['n_chains'] * section['samples_per_chain']}; at least 2 samples are needed "
            "for a standard error")
    return problems


def _debye2020_hard_disks_checks(section: dict, config: dict) -> list[str]:
    """debye2020.hard_disks (equilibrium hard disks, Sec. VI B): the disks must fit the
    image (N >= 2, box >= 2 D (1 + contact_range) + D) and stay on the fluid branch."""
    import math

    prefix = "debye2020.hard_disks"
    problems = _hard_particle_mc_checks(prefix, section)
    side, radius, phi2 = section["L"], section["radius"], section["phi2"]
    n = round(phi2 * side * side / (math.pi * radius * radius))
    if n < 2:
        problems.append(
            f"config key '{prefix}.radius': R = {radius:g} px leaves N = round(phi2 L^2 / (pi R^2)) "
            f"= {n} disks on {side}^2 pixels; need N >= 2 (smaller radius or larger L)")
    shortest = 2 * radius * (2 * (1 + section["mc"]["contact_range"]) + 1)
    if side < shortest:
        problems.append(
            f"config key '{prefix}.radius': the image side L = {side} must be >= "
            f"2 R (2 (1 + mc.contact_range) + 1) = {shortest:g} pixels (the contact shell must "
            "fit half the periodic box)")
    realized = n * math.pi * radius * radius / (side * side)
    if n >= 2 and realized > 0.700:
        problems.append(
            f"config key '{prefix}.phi2': N = {n} disks give a disk fraction {realized:.4f} above "
            "0.700, the end of the stable fluid branch of hard disks")
    return problems


# --------------------------------------------------------------------------- mrj2016


def _mrj2016_equilibrium_checks(section: dict, config: dict) -> list[str]:
    """mrj2016.equilibrium (hard-sphere liquid): the cube must hold the contact shell."""
    import math

    prefix = "mrj2016.equilibrium"
    problems = _hard_particle_mc_checks(prefix, section)
    side = (section["n_particles"] * math.pi / (6.0 * section["phi"])) ** (1.0 / 3.0)
    shortest = 2 * (1 + section["mc"]["contact_range"]) + 1
    if side < shortest:
        problems.append(
            f"config key '{prefix}.n_particles': N = {section['n_particles']} spheres at phi = "
            f"{section['phi']:g} fill a cube of side {side:.3g} D, shorter than "
            f"2 (1 + mc.contact_range) + 1 = {shortest:g} D (the contact shell must fit half the box)")
    return problems


#: the config sections of mrj2016.mrj that each route of :mod:`randmedia.generate.mrj` runs before
#: the polish (its ``route`` key): the one home of this map for the generator (which records only
#: these stages' constants), the workflow (a packing's params hold only these, so a change of
#: another route's constants reruns nothing) and the tests of the kept packings
MRJ_ROUTE_STAGES = {"compression": ("compression", "inflation"), "dilute": ("dilute",)}


def _mrj2016_jammed_checks(section: dict, config: dict) -> list[str]:
    """mrj2016.mrj (MRJ packings): the LP pair cutoffs and the TJ influence sphere must fit
    in the cell, the strain bounds must leave room for a translation bound, the final
    displacement bound must not exceed the first, and the compression must not stop before
    it slows down (equal pressures: a constant growth rate, as mrj_md's)."""
    import math

    problems = []
    polish, lp = section["polish"], section["inflation"]
    reach = 1 + polish["influence_gap"]
    cutoff = 1 + 4 * math.sqrt(3) * lp["displacement_bound"]
    systems = [key for key, value in section.items() if isinstance(value, dict) and "n_particles" in value]
    for system in systems:
        n = section[system]["n_particles"]
        # half the side of a cubic cell at phi = 0.64, with 20 % margin for the cell's shear
        half_width = 0.8 * 0.5 * (n * math.pi / 6 / 0.64) ** (1 / 3)
        for key, value in (("polish.influence_gap", reach),
                           ("inflation.displacement_bound", cutoff)):
            if value > half_width:
                problems.append(
                    f"config key 'mrj2016.mrj.{system}.n_particles': {n} spheres give a jammed "
                    f"cell too small for the pair cutoff {value:.4g} D set by "
                    f"mrj2016.mrj.{key} (must be < {half_width:.3g} D, 0.8 x half the cell "
                    "side); use more spheres or a smaller value")
    strain = polish["max_normal_strain"] + 2 * polish["max_shear_strain"]
    if reach * (1 - strain) <= 1:
        problems.append(
            "config key 'mrj2016.mrj.polish.influence_gap': (1 + influence_gap)(1 - "
            f"max_normal_strain - 2 max_shear_strain) = {reach * (1 - strain):.4g} must be > 1, "
            "or no translation keeps pairs beyond the influence sphere apart")
    if lp["final_displacement_bound"] > lp["displacement_bound"]:
        problems.append(
            "config key 'mrj2016.mrj.inflation.final_displacement_bound': "
            f"{lp['final_displacement_bound']:g} must not exceed displacement_bound "
            f"{lp['displacement_bound']:g}")
    # the shared compression, and each system's own keys over it (mrj_md)
    compressions = [("", section["compression"])] + [
        (f"{system}.", {**section["compression"], **section[system]["compression"]})
        for system in systems if "compression" in section[system]]
    for where, compression in compressions:
        if compression["target_pressure"] < compression["slowdown_pressure"]:
            problems.append(
                f"config key 'mrj2016.mrj.{where}compression.target_pressure': "
                f"{compression['target_pressure']:g} must not be below slowdown_pressure "
                f"{compression['slowdown_pressure']:g}")
    return problems


def _is_multiple(value: float, step: float) -> bool:
    ratio = value / step
    return abs(ratio - round(ratio)) < 1e-6


def _mrj2016_checks(section: dict, config: dict) -> list[str]:
    """mrj2016: overlapping spheres, lattices and the descriptor sections."""
    import math

    problems = []
    r_step = section["descriptors"]["r_step"]
    if not (_is_multiple(0.01, r_step) and _is_multiple(0.09, r_step)):
        problems.append(
            f"config key 'mrj2016.descriptors.r_step': {r_step:g} D must divide 0.01 D and 0.09 D "
            "(every r of Tables II-III must be a grid point)")
    if section["descriptors"]["r_max"] < 0.1:
        problems.append("config key 'mrj2016.descriptors.r_max': must be >= 0.1 D (the grid "
                        f"needs a few points), got {section['descriptors']['r_max']:g}")
    pores = section["pores"]
    if not (_is_multiple(0.5, pores["bin_width"]) and _is_multiple(0.01, pores["bin_width"])):
        problems.append(
            f"config key 'mrj2016.pores.bin_width': {pores['bin_width']:g} D must divide 0.01 D "
            "and the sphere radius 0.5 D (reported r and the matrix boundary must be bin edges)")
    spectral = section["spectral"]
    if spectral["bin_width"] >= spectral["k_max"]:
        problems.append(
            f"config key 'mrj2016.spectral.bin_width': {spectral['bin_width']:g} must be < "
            f"k_max = {spectral['k_max']:g}")
    overlapping = section["overlapping"]
    rho = -math.log1p(-overlapping["phi"]) / (math.pi / 6.0)
    half_width = 0.5 * (overlapping["n_mean"] / rho) ** (1.0 / 3.0)
    windows = section["number_variance"]
    if windows["radius_step"] >= half_width:
        problems.append(
            f"config key 'mrj2016.number_variance.radius_step': {windows['radius_step']:g} D must be "
            f"smaller than the half width {half_width:.3g} D of the overlapping-sphere box "
            "(raise mrj2016.overlapping.n_mean or lower the step)")
    return problems


# --------------------------------------------------------------------------- sphere2019


def _sphere2019_checks(section: dict, config: dict) -> list[str]:
    """sphere2019: point patterns, Monte Carlo fluids, cap statistics."""
    import math

    problems = []
    caps, fit, patterns, fluids = (section[k] for k in ("caps", "fit", "patterns", "fluids"))
    blocks = caps["n_blocks"]
    required = ("lj_R15", "udd_R15", "uddpar_a1_R15", "udc_R15", "ucc_R15", "uddpar_a1_R5",
                "uddpar_a3_R5", "uddpar_a6_R5", "uddcubed_a3_R5", "uddcubed_a6_R5", "udd_flipped_R15")
    missing = [name for name in required if name not in fluids["systems"]]
    if missing:
        problems.append(f"config key 'sphere2019.fluids.systems.{missing[0]}' is required (Table I "
                        f"and Figs. 4-8 need the systems {', '.join(missing)})")
    for name in ("icosahedral", "fibonacci", "uniform", "poisson"):
        if name in fluids["systems"]:
            problems.append(f"config key 'sphere2019.fluids.systems.{name}' is the name of a point "
                            "pattern; choose another name for the fluid")
    if patterns["uncorrelated_configs"] < blocks:
        problems.append(f"config key 'sphere2019.patterns.uncorrelated_configs': "
                        f"{patterns['uncorrelated_configs']} configurations cannot fill "
                        f"caps.n_blocks = {blocks} jackknife blocks")
    if caps["pattern_centres"] < blocks:
        problems.append(f"config key 'sphere2019.caps.pattern_centres': {caps['pattern_centres']} "
                        f"centres cannot fill caps.n_blocks = {blocks} jackknife blocks")
    for name, run in fluids["runs"].items():
        where = f"sphere2019.fluids.runs.{name}"
        production = run["production_sweeps"]
        if run["frame_interval"] > production:
            problems.append(f"config key '{where}.frame_interval': {run['frame_interval']} exceeds "
                            f"production_sweeps = {production} (no configuration would be stored)")
        elif production // run["frame_interval"] < blocks:
            problems.append(f"config key '{where}.frame_interval': production_sweeps / frame_interval "
                            f"= {production // run['frame_interval']} stored configurations cannot "
                            f"fill caps.n_blocks = {blocks} jackknife blocks")
        if production // run["count_interval"] < max(blocks, 4):
            problems.append(f"config key '{where}.count_interval': production_sweeps / count_interval "
                            f"= {production // run['count_interval']} records; need >= "
                            f"max(caps.n_blocks, 4) = {max(blocks, 4)}")

    def window(where: str, radius: float, rho: float) -> None:
        a_min, a_max = fit["a_min_rho_half"] / math.sqrt(rho), fit["a_max_over_R"] * radius
        inside = sum(1 for k in range(1, caps["n_a"] + 1)
                     if a_min <= radius * k / caps["n_a"] <= a_max)
        if inside < 3:
            problems.append(
                f"config key 'sphere2019.fit.a_min_rho_half': the fit window a in [{a_min:.3g}, "
                f"{a_max:.3g}] holds {inside} of the cap radii R k / n_a of {where} (R = {radius:g}); "
                "need >= 3 (lower a_min_rho_half, raise a_max_over_R or caps.n_a)")

    rho_fluid = fluids["density"]
    for name, system in fluids["systems"].items():
        where = f"sphere2019.fluids.systems.{name}"
        if system["run"] not in fluids["runs"]:
            problems.append(f"config key '{where}.run': {system['run']!r} is not a run of "
                            f"sphere2019.fluids.runs ({', '.join(sorted(fluids['runs']))})")
        n = round(rho_fluid * 4 * math.pi * system["R"] ** 2)
        if not 2 <= n <= 65535:
            problems.append(f"config key '{where}.R': N = round(rho 4 pi R^2) = {n} particles; "
                            "need 2 <= N <= 65535")
        else:
            window(f"fluid {name}", system["R"], rho_fluid)
    radius_u = patterns["uncorrelated_R"]
    window("the uniform pattern", radius_u, patterns["uncorrelated_points"] / (4 * math.pi * radius_u**2))
    for label, n in (("the icosahedral grid", 40 * patterns["icosahedral_resolution"]
                      * (patterns["icosahedral_resolution"] - 1) + 12),
                     ("the Fibonacci grid", patterns["fibonacci_points"])):
        window(label, math.sqrt(n / (4 * math.pi * patterns["density"])), patterns["density"])
    return problems


# --------------------------------------------------------------------------- debye3d
# The study's system table and window margin: the workflow rules and the cross-checks read them
# here, below the study (randmedia.studies.debye3d), which computes each system's descriptors.


def debye3d_system_length(params: Mapping) -> float:
    """The system's length unit in voxels: a (Debye media) or the sphere radius R."""
    return float(params["radius"] if params["kind"] == "spheres" else params["a"])


def debye3d_systems(section: Mapping) -> dict[str, dict]:
    """The systems of the 3D Debye study (:mod:`randmedia.studies.debye3d`) from the config
    section ``debye3d``: name -> parameters.

    ``yt_phi{phi2}`` for every configured phi2 (N, a, l_c, schedule of ``media``),
    ``planes_phi{phi2}`` beside each when ``poisson_planes.n_samples`` > 0 (same N, a),
    and ``spheres_phi{phi2}`` from ``overlapping_spheres``. Every entry carries ``kind``,
    ``phi2``, ``N``, ``n_samples`` and its length (``a`` or ``radius``) and ``s2_r_max`` =
    ``s2.r_max_over_length`` x that length, in voxels.

    Parameters
    ----------
    section : Mapping
        The validated ``debye3d`` config section.

    Returns
    -------
    dict
        System name -> parameter dict.
    """
    media, planes, spheres = section["media"], section["poisson_planes"], section["overlapping_spheres"]
    ratio = float(section["s2"]["r_max_over_length"])
    out = {}
    for phi2 in media["phi2"]:
        common = {"phi2": float(phi2), "N": int(media["N"]), "a": float(media["a"])}
        out[f"yt_phi{phi2:g}"] = {"kind": "yt", **common, "lc": float(media["lc"]),
                                  "schedule": dict(media["schedule"]),
                                  "n_samples": int(media["n_samples"])}
        if planes["n_samples"] > 0:
            out[f"planes_phi{phi2:g}"] = {"kind": "planes", **common,
                                          "n_samples": int(planes["n_samples"])}
    out[f"spheres_phi{spheres['phi2']:g}"] = {
        "kind": "spheres", "phi2": float(spheres["phi2"]), "N": int(spheres["N"]),
        "radius": float(spheres["radius"]), "n_samples": int(spheres["n_samples"])}
    for params in out.values():
        params["s2_r_max"] = ratio * debye3d_system_length(params)
    return out


def debye3d_window_margin(interface: Mapping) -> int:
    """The interior margin (sub-voxels) of every window descriptor of a system: the rule of
    :func:`randmedia.numerics.gaussian.default_margin` at the upper end of the sigma
    bracket, so that it holds for every sigma the tuner tries and the tuned s, the surface
    functions, the chords and the pore sizes all use one interior (an earlier version tuned
    on the bracket's interior and measured on the tuned sigma's: on 32^3 windows the two
    differed by 14 voxels per side and s by 40 %)."""
    return default_margin(float(interface["sigma_bracket"][1]), int(interface["supersample"]))


#: config section (dotted path) -> its cross-check function
def _debye3d_checks(section: dict, config: dict) -> list[str]:
    """debye3d: every distance range inside half the periodic image (or window), and the
    Poisson-plane sample count 0 or >= 2 (a standard error needs two)."""
    problems = []
    media = section["media"]
    for key in ("a", "lc"):
        if media[key] >= media["N"] / 2:
            problems.append(f"config key 'debye3d.media.{key}': {media[key]:g} must be < N/2 = "
                            f"{media['N'] / 2:g} (beyond half the periodic image a distance is not unique)")
    if section["poisson_planes"]["n_samples"] == 1:
        problems.append("config key 'debye3d.poisson_planes.n_samples': 1 leaves no standard "
                        "error; use 0 (no Poisson planes) or >= 2")
    for name, params in debye3d_systems(section).items():
        if params["s2_r_max"] >= params["N"] / 2:
            problems.append(
                f"config key 'debye3d.s2.r_max_over_length': S2 of {name} out to "
                f"{params['s2_r_max']:g} voxels must be < N/2 = {params['N'] / 2:g}")
        length = params["s2_r_max"] / section["s2"]["r_max_over_length"]
        r_max = section["interface"]["r_max_over_length"] * length
        if params["kind"] != "planes" and r_max >= params["N"] / 2:
            problems.append(
                f"config key 'debye3d.interface.r_max_over_length': F_sv, F_ss of {name} out to "
                f"{r_max:g} voxels must be < N/2 = {params['N'] / 2:g}")
        if params["kind"] == "planes":
            interior = params["N"] - 2 * debye3d_window_margin(section["interface"]) / section["interface"]["supersample"]
            if r_max >= interior / 2:
                problems.append(
                    f"config key 'debye3d.interface.r_max_over_length' (or 'sigma_bracket'): F_sv, F_ss of "
                    f"window system {name} out to {r_max:g} voxels must be < half the window's interior, "
                    f"{interior / 2:g} voxels (N minus the filter margin of the bracket's upper sigma per face)")
    return problems


CROSS_CHECKS = {
    "debye2020": _debye2020_checks,
    "debye2020.hard_disks": _debye2020_hard_disks_checks,
    "mrj2016": _mrj2016_checks,
    "mrj2016.equilibrium": _mrj2016_equilibrium_checks,
    "mrj2016.mrj": _mrj2016_jammed_checks,
    "sphere2019": _sphere2019_checks,
    "debye3d": _debye3d_checks,
}


def _file_refs(node):
    """Every ``$ref`` to another schema file (no JSON pointer) below ``node``."""
    if isinstance(node, dict):
        ref = node.get("$ref")
        if isinstance(ref, str) and not ref.startswith("#"):
            yield ref
        for value in node.values():
            yield from _file_refs(value)
    elif isinstance(node, list):
        for value in node:
            yield from _file_refs(value)


def schema_registry(path: str | Path):
    """(root schema, referencing.Registry) for the schema at ``path``: every schema file it
    names by a standard JSON-Schema ``$ref`` (a file name of the same folder; each paper
    keeps its section in a file of its own), recursively, registered under its file name."""
    from referencing import Registry, Resource
    from referencing.jsonschema import DRAFT202012

    path = Path(path)
    resources, pending = {}, [(path.name, "the command line")]
    while pending:
        name, named_by = pending.pop()
        if name in resources:
            continue
        target = path.parent / name
        if not target.is_file():
            raise FileNotFoundError(f"{target}: schema file named by $ref in {named_by} does not exist")
        with open(target) as handle:
            resources[name] = yaml.safe_load(handle)
        pending += [(ref.split("#")[0], name) for ref in _file_refs(resources[name])]
    registry = Registry().with_resources(
        (name, Resource.from_contents(contents, default_specification=DRAFT202012))
        for name, contents in resources.items())
    return resources[path.name], registry


def load_schema(path: str | Path) -> dict:
    """The schema at ``path`` with every ``{"$ref": "file.yaml"}`` replaced, recursively, by
    the schema in that file -- one nested document, for reading (validation resolves the
    references itself: :func:`schema_registry`)."""
    root, registry = schema_registry(path)

    def inline(node, chain):
        if isinstance(node, dict):
            ref = node.get("$ref")
            if isinstance(ref, str) and not ref.startswith("#"):
                if ref in chain:
                    raise ValueError(f"schema $ref cycle: {' -> '.join(chain + (ref,))}")
                rest = {k: v for k, v in node.items() if k != "$ref"}
                return {**inline(registry.contents(ref), chain + (ref,)), **inline(rest, chain)}
            return {key: inline(value, chain) for key, value in node.items()}
        if isinstance(node, list):
            return [inline(value, chain) for value in node]
        return node

    return inline(root, (Path(path).name,))


def validate_config(config: MutableMapping[str, Any], schema_path: str | Path) -> MutableMapping:
    """Validate ``config`` in place (defaults filled); raise :class:`ConfigError` if invalid."""
    schema, registry = schema_registry(schema_path)
    validator = _Validator(schema, registry=registry)
    errors = sorted(validator.iter_errors(config), key=lambda e: list(map(str, e.absolute_path)))
    problems = [_describe(e) for e in errors]
    if not problems:
        problems = _cross_checks(config)
    if problems:
        raise ConfigError("invalid configuration:\n  " + "\n  ".join(problems))
    return config
