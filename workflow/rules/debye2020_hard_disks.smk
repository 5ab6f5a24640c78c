# Ma & Torquato, PRE 102, 043310 (2020), Sec. VI B: equilibrium hard disks at
# phi2 = 0.3 by NVT Monte Carlo (randmedia.generate.hard_spheres, the same
# d-generic code as the mrj2016 hard-sphere liquid), digitized to images.
# Included before debye2020.smk, whose descriptor rules read these samples.
