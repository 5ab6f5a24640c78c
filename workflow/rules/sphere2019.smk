# Hyperuniformity on spherical surfaces, PRE 100, 022107 (2019).
#
# Nothing of this paper is built yet (issue #5), so it has no targets: the
# named targets sphere2019, sphere2019_figNN and sphere2019_table1 are added
# here with the science that produces them, never as placeholders.

SPHERE2019_TARGETS = []
