# The two equilibrium hard-particle systems, made by the same d-generic NVT Monte Carlo
# (randmedia.generate.hard_particles) and the same two scripts (../scripts/hard_particles/):
#   hard_disks    Ma & Torquato, PRE 102, 043310 (2020), Sec. VI B: disks at phi2 = 0.3,
#                 digitized to images (config debye2020.hard_disks; rules debye2020_hard_disks*)
#   hard_spheres  Klatt & Torquato, PRE 94, 022152 (2016): the liquid at phi = 0.478, system
#                 `equilibrium` (config mrj2016.equilibrium; rules mrj2016_equilibrium*)
# One job per Markov chain writes that chain's samples k = chain * samples_per_chain + j (one
# rule per chain: {prefix}_chain{c}); it checkpoints beside them. A validation rule per system
# compares the contact-value pressure with the EOS. Included before debye2020.smk and
# mrj2016.smk, whose descriptor rules read these names:
#   HARD_DISKS, HARD_DISKS_SAMPLES, HARD_DISKS_TARGETS       results/debye2020/hard_disks/
#       phi{phi2:g}/sample{k}.nc (variables phase (y, x) uint8, 1 = disks; position, box in pixels)
#   MRJ2016_EQUILIBRIUM, EQUILIBRIUM_SAMPLES, EQUILIBRIUM_TARGETS   results/mrj2016/configs/
#       equilibrium/sample{k}.nc (PARTICLE_CONFIG: position, box in units of D = 1; attr diameter)
# (the targets: the EOS figure as PDF and PNG, diagnostics.csv, comparison.csv).

HARD_DISKS = config["debye2020"]["hard_disks"]
MRJ2016_EQUILIBRIUM = config["mrj2016"]["equilibrium"]

#: per system: rule-name prefix, config section, sample folder, validation stem, report paper,
#: and the parameters of the chain and validation scripts beyond those every system has (the
#: aggregate rule {prefix} asks for every sample and the validation)
HARD_PARTICLE_SYSTEMS = {
    "hard_disks": {
        "prefix": "debye2020_hard_disks", "section": HARD_DISKS,
        "folder": results_path(f"debye2020/hard_disks/phi{HARD_DISKS['phi2']:g}"),
        "validation": results_path("debye2020/validation/hard_disks"), "paper": "debye2020",
        "chain_params": {key: HARD_DISKS[key] for key in ("phi2", "L", "radius")},
        "validation_params": {key: HARD_DISKS[key] for key in ("phi2", "radius")},
    },
    "hard_spheres": {
        "prefix": "mrj2016_equilibrium", "section": MRJ2016_EQUILIBRIUM,
        "folder": results_path("mrj2016/configs/equilibrium"),
        "validation": results_path("mrj2016/validation/equilibrium"), "paper": "mrj2016",
        "chain_params": {key: MRJ2016_EQUILIBRIUM[key] for key in ("phi", "n_particles", "eos")},
        "validation_params": {key: MRJ2016_EQUILIBRIUM[key] for key in ("phi", "eos")},
    },
}
for _system in HARD_PARTICLE_SYSTEMS.values():
    _system["samples"] = [f"{_system['folder']}/sample{k}.nc" for k in
                          range(_system["section"]["n_chains"] * _system["section"]["samples_per_chain"])]
    _system["targets"] = [f"{_system['validation']}_{suffix}"
                          for suffix in ("eos.pdf", "eos.png", "diagnostics.csv", "comparison.csv")]
HARD_DISKS_SAMPLES = HARD_PARTICLE_SYSTEMS["hard_disks"]["samples"]
HARD_DISKS_TARGETS = HARD_PARTICLE_SYSTEMS["hard_disks"]["targets"]
EQUILIBRIUM_SAMPLES = HARD_PARTICLE_SYSTEMS["hard_spheres"]["samples"]
EQUILIBRIUM_TARGETS = HARD_PARTICLE_SYSTEMS["hard_spheres"]["targets"]

for _name, _system in HARD_PARTICLE_SYSTEMS.items():
    _per_chain = _system["section"]["samples_per_chain"]
    _paper, _stem = _system["paper"], _system["prefix"][len(_system["paper"]) + 1:]

    for _chain in range(_system["section"]["n_chains"]):

        rule:
            name:
                f"{_system['prefix']}_chain{_chain}"
            input:
                code=script_sources("../scripts/hard_particles/chain.py"),
            output:
                _system["samples"][_chain * _per_chain:(_chain + 1) * _per_chain],
            params:
                system=_name,
                chain=_chain,
                samples_per_chain=_per_chain,
                mc=_system["section"]["mc"],
                checkpoint_seconds=_system["section"]["checkpoint_seconds"],
                seed=config["seed"],
                **_system["chain_params"],
            benchmark:
                results_path(f"{_paper}/benchmarks/{_stem}_chain{_chain}.tsv")
            log:
                results_path(f"{_paper}/logs/{_stem}_chain{_chain}.log"),
            threads: 1
            resources:
                mem_mb=1000,
            script:
                "../scripts/hard_particles/chain.py"

    rule:
        """Contact-value pressure of the chains against the EOS; per-sample diagnostics
        (acceptance, MSD between samples; digitized area fraction or bond order)."""
        name:
            f"{_system['prefix']}_validation"
        input:
            samples=_system["samples"],
            code=script_sources("../scripts/hard_particles/validation.py"),
        output:
            pdf=_system["targets"][0],
            png=report_validation_figure(_system["targets"][1], _paper, f"validation_{_stem}_eos.rst"),
            diagnostics=_system["targets"][2],
            comparison=_system["targets"][3],
        params:
            system=_name,
            mc=_system["section"]["mc"],
            k_sigma=config["comparison"]["k_sigma"],
            **_system["validation_params"],
        benchmark:
            results_path(f"{_paper}/benchmarks/{_stem}_validation.tsv")
        log:
            results_path(f"{_paper}/logs/{_stem}_validation.log"),
        script:
            "../scripts/hard_particles/validation.py"

    rule:
        name:
            _system["prefix"]
        input:
            _system["samples"],
            _system["targets"],
