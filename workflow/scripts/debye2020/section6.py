"""Rules debye2020_fig09 ... debye2020_fig12: the three models at the comparison phi2 (Sec. VI)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.describe.chords import CHORDS
from randmedia.describe.pore_size import PORES
from randmedia.describe.surface import SURFACE
from randmedia.io import read_dataset
from randmedia.plot.debye2020 import section6_figure

params = dict(snakemake.params.items())
specs = {"surface": (SURFACE, ["phi2", "length_scale"]), "pores": (PORES, ["phi2"]),
         "chords": (CHORDS, ["phi2"])}
data = {}
for name, path in snakemake.input.items():
    if name == "code":
        continue
    kind = name.split("_", 1)[1]
    spec, attrs = specs[kind]
    data[name] = read_dataset(path, spec, attrs=attrs)
section6_figure(params["number"], a=params["a"], radius=params["radius"], phi2=params["phi2"],
                pdf_path=snakemake.output.pdf, **data)
