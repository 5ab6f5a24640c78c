# Klatt & Torquato, PRE 94, 022152 (2016): MRJ packings by the Torquato-Jiao
# sequential linear programming algorithm (systems `mrj` and `mrj_large`).
# Included before mrj2016.smk.
