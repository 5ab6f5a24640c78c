"""Invalid configurations, each with the config key its error message must name.

Each case mutates a copy of the quick config (config/quick.yaml merged over config/config.yaml). Used by test_config.py (the
validator directly) and test_workflow.py (Snakemake must refuse them before
any job runs).
"""

from __future__ import annotations

import copy

from conftest import quick_config


def _set(path, value):
    def mutate(cfg):
        node = cfg
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = value
    return mutate


def _delete(path):
    def mutate(cfg):
        node = cfg
        for key in path[:-1]:
            node = node[key]
        del node[path[-1]]
    return mutate


DISKS = ("debye2020", "overlapping_disks")
MEDIA = ("debye2020", "media")
INTERFACE = ("debye2020", "interface")
FITS = ("debye2020", "fits")

#: (case id, mutation, text the error message must contain)
BAD_CONFIGS = [
    ("results_dir_absolute", _set(("results_dir",), "/tmp/out"), "results_dir"),
    ("results_dir_wildcard", _set(("results_dir",), "results/{paper}"), "results_dir"),
    ("L_zero", _set(DISKS + ("L",), 0), "debye2020.overlapping_disks.L"),
    ("L_negative", _set(DISKS + ("L",), -201), "debye2020.overlapping_disks.L"),
    ("L_string", _set(DISKS + ("L",), "201"), "debye2020.overlapping_disks.L"),
    ("L_float", _set(DISKS + ("L",), 201.5), "debye2020.overlapping_disks.L"),
    ("L_bool", _set(DISKS + ("L",), True), "debye2020.overlapping_disks.L"),
    ("radius_zero", _set(DISKS + ("radius",), 0), "debye2020.overlapping_disks.radius"),
    ("radius_negative", _set(DISKS + ("radius",), -6.0), "debye2020.overlapping_disks.radius"),
    ("radius_vs_L", _set(DISKS + ("radius",), 20.0), "debye2020.overlapping_disks.radius"),
    ("radius_wraps_torus", lambda c: c["debye2020"]["overlapping_disks"].update(
        radius=70.0, s2_r_max_over_R=1.0, compare_r_max_over_R=1.0),
     "debye2020.overlapping_disks.radius"),
    ("phi2_zero", _set(DISKS + ("phi2",), 0.0), "debye2020.overlapping_disks.phi2"),
    ("phi2_one", _set(DISKS + ("phi2",), 1.0), "debye2020.overlapping_disks.phi2"),
    ("phi2_above_one", _set(DISKS + ("phi2",), 1.3), "debye2020.overlapping_disks.phi2"),
    ("phi2_negative", _set(DISKS + ("phi2",), -0.3), "debye2020.overlapping_disks.phi2"),
    ("phi2_null", _set(DISKS + ("phi2",), None), "debye2020.overlapping_disks.phi2"),
    ("n_samples_one", _set(DISKS + ("n_samples",), 1), "debye2020.overlapping_disks.n_samples"),
    ("n_samples_fraction", _set(DISKS + ("n_samples",), 2.5), "debye2020.overlapping_disks.n_samples"),
    ("s2_range_zero", _set(DISKS + ("s2_r_max_over_R",), 0), "debye2020.overlapping_disks.s2_r_max_over_R"),
    ("compare_beyond_s2", _set(DISKS + ("compare_r_max_over_R",), 7.0),
     "debye2020.overlapping_disks.compare_r_max_over_R"),
    ("media_lc_half_L", _set(MEDIA + ("lc",), 60.5), "debye2020.media.lc"),
    ("media_a_half_L", _set(MEDIA + ("a",), 61.0), "debye2020.media.a"),
    ("media_a_zero", _set(MEDIA + ("a",), 0.0), "debye2020.media.a"),
    ("media_phi2_item_one", _set(MEDIA + ("phi2",), [0.1, 1.0]), "debye2020.media.phi2.1"),
    ("media_phi2_empty", _set(MEDIA + ("phi2",), []), "debye2020.media.phi2"),
    ("media_phi2_repeated", _set(MEDIA + ("phi2",), [0.3, 0.3]), "debye2020.media.phi2"),
    ("media_schedule_unknown", _set(MEDIA + ("schedule", "cooling"), 0.9),
     "debye2020.media.schedule.cooling"),
    ("media_L_list", _set(MEDIA + ("L",), [121, 131]), "debye2020.media.L"),
    ("interface_model_unknown", _set(INTERFACE + ("model",), "spline"), "debye2020.interface.model"),
    ("interface_bracket_reversed", _set(INTERFACE + ("sigma_bracket",), [2.0, 0.5]),
     "debye2020.interface.sigma_bracket"),
    ("interface_bin_not_subpixel", _set(INTERFACE + ("bin_width",), 0.3), "debye2020.interface.bin_width"),
    ("interface_r_max_half_L", _set(INTERFACE + ("r_max_over_length",), 25.0),
     "debye2020.interface.r_max_over_length"),
    ("fits_euler_beyond_r_max", _set(FITS + ("euler_fit_r_max_alt_over_a",), 9.0),
     "debye2020.fits.euler_fit_r_max_alt_over_a"),
    ("fits_pore_F_min_one", _set(FITS + ("pore_fit_F_min",), 1.0), "debye2020.fits.pore_fit_F_min"),
    ("disks_phi2_not_a_media_phi2", _set(DISKS + ("phi2",), 0.35), "debye2020.overlapping_disks.phi2"),
    ("k_sigma_negative", _set(("comparison", "k_sigma"), -3.0), "comparison.k_sigma"),
    ("seed_negative", _set(("seed",), -1), "seed"),
    ("unknown_top_key", _set(("sead",), 1), "sead"),
    ("unknown_nested_key", _set(DISKS + ("radious",), 6.0), "debye2020.overlapping_disks.radious"),
    ("missing_L", _delete(DISKS + ("L",)), "debye2020.overlapping_disks.L"),
    ("missing_seed", _delete(("seed",)), "seed"),
    ("missing_section", _delete(("debye2020",)), "debye2020"),
    ("section_not_mapping", _set(("debye2020",), [1, 2]), "debye2020"),
]

# equilibrium hard disks (debye2020.hard_disks) and the hard-sphere liquid (mrj2016.equilibrium)
HARD_DISKS = ("debye2020", "hard_disks")
LIQUID = ("mrj2016", "equilibrium")
BAD_CONFIGS += [
    ("hard_disks_phi2_above_fluid_branch", _set(HARD_DISKS + ("phi2",), 0.75),
     "debye2020.hard_disks.phi2"),
    ("hard_disks_radius_vs_L", _set(HARD_DISKS + ("radius",), 40.0), "debye2020.hard_disks.radius"),
    ("hard_disks_radius_negative", _set(HARD_DISKS + ("radius",), -6.0),
     "debye2020.hard_disks.radius"),
    ("hard_disks_one_sample", lambda c: c["debye2020"]["hard_disks"].update(
        n_chains=1, samples_per_chain=1), "debye2020.hard_disks.samples_per_chain"),
    ("hard_disks_sample_msd_below_one", _set(HARD_DISKS + ("mc", "sample_msd"), 0.5),
     "debye2020.hard_disks.mc.sample_msd"),
    ("liquid_phi_above_freezing", _set(LIQUID + ("phi",), 0.55), "mrj2016.equilibrium.phi"),
    ("liquid_too_few_particles", _set(LIQUID + ("n_particles",), 20),
     "mrj2016.equilibrium.n_particles"),
    ("liquid_contact_bins_vs_order", _set(LIQUID + ("mc", "contact_bins"), 4),
     "mrj2016.equilibrium.mc.contact_bins"),
    ("liquid_unknown_eos", _set(LIQUID + ("eos",), "percus_yevick"), "mrj2016.equilibrium.eos"),
]

SPHERE_FLUIDS = ("sphere2019", "fluids")
SPHERE_SYSTEMS = SPHERE_FLUIDS + ("systems",)

BAD_CONFIGS += [
    ("sphere_R_zero", _set(SPHERE_SYSTEMS + ("lj_R15", "R"), 0.0), "sphere2019.fluids.systems.lj_R15.R"),
    ("sphere_density_negative", _set(SPHERE_FLUIDS + ("density",), -0.5), "sphere2019.fluids.density"),
    ("sphere_temperature_zero", _set(SPHERE_FLUIDS + ("temperature",), 0.0),
     "sphere2019.fluids.temperature"),
    ("sphere_unknown_potential", _set(SPHERE_SYSTEMS + ("udc_R15", "potential"), "yukawa"),
     "sphere2019.fluids.systems.udc_R15.potential"),
    ("sphere_a_beyond_R", _set(("sphere2019", "fit", "a_max_over_R"), 1.5), "sphere2019.fit.a_max_over_R"),
    ("sphere_unknown_run", _set(SPHERE_SYSTEMS + ("ucc_R15", "run"), "R30"),
     "sphere2019.fluids.systems.ucc_R15.run"),
    ("sphere_missing_system", _delete(SPHERE_SYSTEMS + ("udd_R15",)), "sphere2019.fluids.systems.udd_R15"),
    ("sphere_frames_beyond_run", _set(SPHERE_FLUIDS + ("runs", "R5", "frame_interval"), 10**6),
     "sphere2019.fluids.runs.R5.frame_interval"),
    ("sphere_empty_fit_window", _set(("sphere2019", "fit", "a_min_rho_half"), 50.0),
     "sphere2019.fit.a_min_rho_half"),
    ("sphere_ico_resolution_one", _set(("sphere2019", "patterns", "icosahedral_resolution"), 1),
     "sphere2019.patterns.icosahedral_resolution"),
]


def bad_config(mutation) -> dict:
    config = copy.deepcopy(quick_config())
    mutation(config)
    return config

MRJ2016 = ("mrj2016",)

# mrj2016: overlapping spheres, lattices, descriptors (Klatt & Torquato 2016)
BAD_CONFIGS += [
    ("mrj_overlapping_phi_one", _set(MRJ2016 + ("overlapping", "phi"), 1.0), "mrj2016.overlapping.phi"),
    ("mrj_fcc_cells_one", _set(MRJ2016 + ("lattices", "fcc_cells"), 1), "mrj2016.lattices.fcc_cells"),
    ("mrj_r_step_not_dividing_table", _set(MRJ2016 + ("descriptors", "r_step"), 0.007), "mrj2016.descriptors.r_step"),
    ("mrj_pore_bin_not_dividing_radius", _set(MRJ2016 + ("pores", "bin_width"), 0.003), "mrj2016.pores.bin_width"),
    ("mrj_spectral_bin_beyond_k_max", _set(MRJ2016 + ("spectral", "bin_width"), 25.0), "mrj2016.spectral.bin_width"),
    ("mrj_phi_B_zero", _set(MRJ2016 + ("number_variance", "phi_B"), 0.0), "mrj2016.number_variance.phi_B"),
    ("mrj_window_step_beyond_box", _set(MRJ2016 + ("number_variance", "radius_step"), 4.0),
     "mrj2016.number_variance.radius_step"),
    ("mrj_missing_pores", _delete(MRJ2016 + ("pores",)), "mrj2016.pores"),
]

MRJ = ("mrj2016", "mrj")
BAD_CONFIGS += [
    ("mrj_n_particles_small", _set(MRJ + ("mrj", "n_particles"), 20), "mrj2016.mrj.mrj.n_particles"),
    ("mrj_n_particles_cell", lambda c: (c["mrj2016"]["mrj"]["mrj_large"].update(n_particles=60),
                                        c["mrj2016"]["mrj"]["polish"].update(influence_gap=0.6)),
     "mrj2016.mrj.mrj_large.n_particles"),
    ("mrj_n_samples_negative", _set(MRJ + ("mrj", "n_samples"), -1), "mrj2016.mrj.mrj.n_samples"),
    ("mrj_influence_gap_vs_strain", lambda c: c["mrj2016"]["mrj"]["polish"].update(
        influence_gap=0.02, max_normal_strain=0.01, max_shear_strain=0.01),
     "mrj2016.mrj.polish.influence_gap"),
    ("mrj_backend_unknown", _set(MRJ + ("polish", "backend"), "glpk"), "mrj2016.mrj.polish.backend"),
    ("mrj_tolerance_zero", _set(MRJ + ("polish", "tolerance"), 0.0), "mrj2016.mrj.polish.tolerance"),
    ("mrj_growth_negative", _set(MRJ + ("compression", "growth_rate"), -0.1),
     "mrj2016.mrj.compression.growth_rate"),
    ("mrj_target_below_slowdown", _set(MRJ + ("compression", "target_pressure"), 40.0),
     "mrj2016.mrj.compression.target_pressure"),
    ("mrj_md_target_below_its_slowdown", _set(MRJ + ("mrj_md", "compression", "target_pressure"), 1e5),
     "mrj2016.mrj.mrj_md.compression.target_pressure"),
    ("mrj_md_route_not_md", _set(MRJ + ("mrj_md", "route"), "dilute"), "mrj2016.mrj.mrj_md.route"),
    ("mrj_bound_negative", _set(MRJ + ("inflation", "displacement_bound"), -0.01),
     "mrj2016.mrj.inflation.displacement_bound"),
    ("mrj_final_bound_above_first", _set(MRJ + ("inflation", "final_displacement_bound"), 0.01),
     "mrj2016.mrj.inflation.final_displacement_bound"),
    ("mrj_bound_beyond_cell", lambda c: (c["mrj2016"]["mrj"]["mrj_large"].update(n_particles=60),
                                         c["mrj2016"]["mrj"]["inflation"].update(displacement_bound=0.2)),
     "mrj2016.mrj.mrj_large.n_particles"),
    ("mrj_gap_tolerance_big", _set(MRJ + ("contacts", "gap_tolerance"), 0.01),
     "mrj2016.mrj.contacts.gap_tolerance"),
    ("mrj_unknown_key", _set(MRJ + ("n_particles",), 2000), "mrj2016.mrj.n_particles"),
]

# beyond the papers: 3D Debye media (debye3d)
BAD_CONFIGS += [
    ("debye3d_lc_half_image", _set(("debye3d", "media", "lc"), 16.0), "debye3d.media.lc"),
    ("debye3d_one_plane_window", _set(("debye3d", "poisson_planes", "n_samples"), 1),
     "debye3d.poisson_planes.n_samples"),
    ("debye3d_s2_beyond_half", _set(("debye3d", "s2", "r_max_over_length"), 8.0),
     "debye3d.s2.r_max_over_length"),
    ("debye3d_unknown_key", _set(("debye3d", "media", "L"), 64), "debye3d.media.L"),
    # a wide sigma bracket leaves a 6-voxel interior in the 32^3 windows: F_sv out to 9 voxels cannot fit
    ("debye3d_window_interior_too_small", _set(("debye3d", "interface", "sigma_bracket"), [0.1, 3.0]),
     "debye3d.interface.r_max_over_length"),
]
