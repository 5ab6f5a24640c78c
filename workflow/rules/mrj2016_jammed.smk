# Klatt & Torquato, PRE 94, 022152 (2016): strictly jammed sphere packings -- the MRJ systems
# `mrj` and `mrj_large` by the paper's route (Torquato-Jiao LPs from a dilute start), the
# MD-like system `mrj_md` (the packings of the paper's Ref. [29]) by a Lubachevsky-Stillinger
# compression, inflation LPs in the fixed cell and the same Torquato-Jiao polish
# (randmedia.generate.mrj).
# Included before mrj2016.smk.
#
# Python names other rule files use:
#   MRJ_JAMMED         the config section mrj2016.mrj
#   MRJ_SAMPLES        every results/mrj2016/configs/mrj/sample{k}.nc
#   MRJ_LARGE_SAMPLES  every results/mrj2016/configs/mrj_large/sample{k}.nc
#   MRJ_MD_SAMPLES     every results/mrj2016/configs/mrj_md/sample{k}.nc
#   JAMMED_TARGETS     packings.csv (phi, z, rattler fraction, Q6 per packing; mean, SEM)

MRJ_JAMMED = config["mrj2016"]["mrj"]
MRJ_PACKING = results_path("mrj2016/configs/{system}/sample{k}.nc")
#: measured CPU of one packing by the paper's route at N = 2000: the median of the eight kept
#: packings (1652-8037 s; docs/mrj2016.md, "Routes compared")
MRJ_PACKING_CPU_SECONDS = 3394
#: how that CPU grows with N, taken as N^2 (HiPO TJ LP ~N^1.6, dilute LP count ~N^0.4): 24 CPU h at
#: N = 10 000, the runtime request 3x that; the first N = 10 000 packing took 33.4 CPU h (both of
#: its stages ended at their LP caps; docs/mrj2016.md, "N = 10 000"); a job killed at a queue's
#: time limit resumes from the packing's checkpoint when Snakemake runs it again
MRJ_PACKING_CPU_EXPONENT = 2.0
MRJ_SAMPLES = expand(MRJ_PACKING, system="mrj", k=range(MRJ_JAMMED["mrj"]["n_samples"]))
MRJ_LARGE_SAMPLES = expand(MRJ_PACKING, system="mrj_large",
                           k=range(MRJ_JAMMED["mrj_large"]["n_samples"]))
MRJ_MD_SAMPLES = expand(MRJ_PACKING, system="mrj_md", k=range(MRJ_JAMMED["mrj_md"]["n_samples"]))
#: the jammed systems of the section mrj2016.mrj
MRJ_JAMMED_SYSTEMS = ("mrj", "mrj_large", "mrj_md")
MRJ_PACKINGS_TABLE = results_path("mrj2016/packings.csv")
#: the contact-gap ladder of one packing (rule mrj2016_packing_certificate), beside the packing
MRJ_CERTIFICATE = results_path("mrj2016/configs/{system}/sample{k}.certificate.csv")

JAMMED_TARGETS = [MRJ_PACKINGS_TABLE]


rule mrj2016_jammed_packing:
    """One strictly jammed packing (compression, inflation LPs, Torquato-Jiao polish);
    checkpoints and resumes."""
    input:
        code=script_sources("../scripts/mrj2016/jammed_packing.py"),
    output:
        MRJ_PACKING,
    wildcard_constraints:
        system="|".join(MRJ_JAMMED_SYSTEMS),
    params:
        n_particles=lambda wildcards: MRJ_JAMMED[wildcards.system]["n_particles"],
        # only the stages of the configured route, so a change of the other route's
        # constants reruns nothing
        route=lambda wildcards: mrj_stage(MRJ_JAMMED, wildcards.system, "route"),
        compression=lambda wildcards: mrj_route_stage(MRJ_JAMMED, wildcards.system, "compression"),
        inflation=lambda wildcards: mrj_route_stage(MRJ_JAMMED, wildcards.system, "inflation"),
        dilute=lambda wildcards: mrj_route_stage(MRJ_JAMMED, wildcards.system, "dilute"),
        polish=lambda wildcards: mrj_stage(MRJ_JAMMED, wildcards.system, "polish"),
        contacts=lambda wildcards: mrj_stage(MRJ_JAMMED, wildcards.system, "contacts"),
        bond_order_cutoff=MRJ_JAMMED["bond_order_cutoff"],
        checkpoint_seconds=MRJ_JAMMED["checkpoint_seconds"],
        seed=config["seed"],
        # every packing is kept beside the record as it finishes and taken back from there
        # (same seed and configuration) instead of regenerated: record/packings/mrj2016/ for
        # the paper config's packings (any sample count), {results_dir}/record/... for others; outside
        # record/mrj2016/, which the record rule replaces as a whole
        keep_dir=lambda wildcards: mrj_keep_dir(wildcards.system),
    benchmark:
        results_path("mrj2016/benchmarks/jammed_packing_{system}_sample{k}.tsv")
    log:
        results_path("mrj2016/logs/jammed_{system}_sample{k}.log"),
    threads: 1
    resources:
        # HiGHS IPX: ~2 GB for one LP of 16 000 spheres; the jamming test's sparse LU of B^T B:
        # 1.7e8 nonzeros (~2.5 GB) at 10 000 spheres, scaled with N^1.5 (both measured)
        mem_mb=lambda wildcards: int(500 + MRJ_JAMMED[wildcards.system]["n_particles"] / 4
                                     + 2500 * (MRJ_JAMMED[wildcards.system]["n_particles"] / 10000) ** 1.5),
        # minutes, for cluster queues: 3x the median CPU of a paper-route packing at N = 2000
        # (MRJ_PACKING_CPU_SECONDS), scaled with N^2 (MRJ_PACKING_CPU_EXPONENT)
        runtime=lambda wildcards: max(30, int(3 * MRJ_PACKING_CPU_SECONDS / 60
                                              * (MRJ_JAMMED[wildcards.system]["n_particles"] / 2000) ** MRJ_PACKING_CPU_EXPONENT)),
    script:
        "../scripts/mrj2016/jammed_packing.py"


rule mrj2016_packing_certificate:
    """The strict-jamming test of one packing at the configured contact gap tolerance, then at
    10x, 100x, ... up to 1e-4 D until it passes: one row per rung (its certified gap tolerance)."""
    input:
        packing=MRJ_PACKING,
        code=script_sources("../scripts/mrj2016/packing_certificate.py"),
    output:
        MRJ_CERTIFICATE,
    wildcard_constraints:
        system="|".join(MRJ_JAMMED_SYSTEMS),
    params:
        contacts=lambda wildcards: mrj_stage(MRJ_JAMMED, wildcards.system, "contacts"),
        # the ladder is kept beside the kept packing and taken back for the same packing,
        # contact options and code (randmedia.kept_certificates)
        keep_dir=lambda wildcards: mrj_keep_dir(wildcards.system),
    benchmark:
        results_path("mrj2016/benchmarks/packing_certificate_{system}_sample{k}.tsv")
    log:
        results_path("mrj2016/logs/packing_certificate_{system}_sample{k}.log"),
    threads: 1
    resources:
        # the jamming test's sparse LU of B^T B, as in the packing rule: ~2.5 GB at 10 000 spheres
        mem_mb=lambda wildcards: int(500 + 2500 * (MRJ_JAMMED[wildcards.system]["n_particles"] / 10000) ** 1.5),
        # minutes: an uncertified N = 10 000 packing's ladder took 42 min (two rungs with a backbone)
        runtime=lambda wildcards: max(10, int(120 * (MRJ_JAMMED[wildcards.system]["n_particles"] / 10000) ** 2)),
    script:
        "../scripts/mrj2016/packing_certificate.py"


rule mrj2016_packings:
    """packings.csv: phi, mean contact number, rattler fraction, Q6, crystal-like fraction,
    jamming test, certified gap tolerance and cost of every packing, with mean and SEM per
    system."""
    input:
        samples=MRJ_SAMPLES + MRJ_LARGE_SAMPLES + MRJ_MD_SAMPLES,
        # sample{k}.nc -> sample{k}.certificate.csv, in the same order
        certificates=[path.removesuffix(".nc") + ".certificate.csv"
                      for path in MRJ_SAMPLES + MRJ_LARGE_SAMPLES + MRJ_MD_SAMPLES],
        code=script_sources("../scripts/mrj2016/jammed_packings.py"),
    output:
        MRJ_PACKINGS_TABLE,
    benchmark:
        results_path("mrj2016/benchmarks/packings.tsv")
    log:
        results_path("mrj2016/logs/packings.log"),
    script:
        "../scripts/mrj2016/jammed_packings.py"


rule mrj2016_jammed:
    """Named target: every MRJ packing and their summary."""
    input:
        JAMMED_TARGETS,
