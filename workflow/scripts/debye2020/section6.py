"""Rules debye2020_fig09 ... debye2020_fig12: the three models at the comparison phi2 (Sec. VI)."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.describe.chords import CHORDS  # noqa: E402
from randmedia.describe.pore_size import PORES  # noqa: E402
from randmedia.describe.surface import SURFACE  # noqa: E402
from randmedia.io import read_dataset  # noqa: E402
from randmedia.plot.debye2020 import section6_figure  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
specs = {"surface": (SURFACE, ["phi2", "length_scale"]), "pores": (PORES, ["phi2"]),
         "chords": (CHORDS, ["phi2"])}
data = {}
for name, path in snakemake.input.items():  # noqa: F821
    if name == "code":
        continue
    kind = name.split("_", 1)[1]
    spec, attrs = specs[kind]
    data[name] = read_dataset(path, spec, attrs=attrs)
section6_figure(params["number"], a=params["a"], radius=params["radius"], phi2=params["phi2"],
                pdf_path=snakemake.output.pdf, **data)  # noqa: F821
