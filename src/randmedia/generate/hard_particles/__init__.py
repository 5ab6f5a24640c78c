"""Equilibrium hard disks (d = 2) and hard spheres (d = 3) by NVT Monte Carlo.

One d-generic implementation serves Ma & Torquato 2020, Sec. VI B (hard disks at
phi2 = 0.3 on the stable fluid branch) and Klatt & Torquato 2016 (the hard-sphere
liquid at phi = 0.478). N identical particles of diameter D in a periodic
orthogonal box; the equilibrium (Gibbs) measure is uniform over non-overlapping
configurations. Method and choices: docs/hard_particles.md.

One job per module (import from them directly):

* :mod:`~randmedia.generate.hard_particles.settings` -- the constants of a chain
  (:class:`MCSettings`) and :class:`ChainError`;
* :mod:`~randmedia.generate.hard_particles.geometry` -- box at a packing fraction,
  input checks (stable fluid branch), lattice starts, exact overlap count;
* :mod:`~randmedia.generate.hard_particles.kernels` -- the numba kernels: cell list,
  displacement sweeps, pair scan near contact, random sequential addition;
* :mod:`~randmedia.generate.hard_particles.chain` -- the Markov chain (moves, stages
  start / compress / equilibrate / calibrate / produce, its checkpointable state);
* :mod:`~randmedia.generate.hard_particles.contact` -- g(D+) and the reduced pressure
  from the pair counts near contact;
* :mod:`~randmedia.generate.hard_particles.run` -- :func:`run_chain`, the resumable
  driver (checkpoints, progress log, final overlap check);
* :mod:`~randmedia.generate.hard_particles.datasets` -- per-sample netCDF attributes and
  the contact-histogram dataset of the sample files.
"""
