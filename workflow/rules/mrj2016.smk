# Klatt & Torquato, PRE 94, 022152 (2016): MRJ sphere packings II.
#
# Nothing of this paper is built yet (issue #4), so it has no targets: the
# named targets mrj2016, mrj2016_figNN and mrj2016_tableN are added here with
# the science that produces them, never as placeholders.

MRJ2016_TARGETS = []
