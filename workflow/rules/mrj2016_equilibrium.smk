# Klatt & Torquato, PRE 94, 022152 (2016): the equilibrium hard-sphere liquid
# at phi = 0.478 (system `equilibrium`) by NVT Monte Carlo
# (randmedia.generate.hard_spheres, d-generic). Included before mrj2016.smk.
