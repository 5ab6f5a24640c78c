"""What the sample files of a hard-particle chain carry besides the positions: the
per-sample and per-chain diagnostics as netCDF attributes, and the pair counts near
contact as a re-fittable dataset."""

from __future__ import annotations

import numpy as np

from randmedia.generate.hard_particles.chain import ChainResult
from randmedia.generate.hard_particles.settings import MCSettings


def sample_attrs(result: ChainResult, index: int) -> dict:
    """The diagnostics of sample ``index`` of a chain, as flat netCDF attributes: its own
    (MSD since the previous sample in D^2, sweeps, acceptance, contact value, reduced
    pressure) and the chain's (start, equilibration, frozen step, sampling interval)."""
    sample = result.samples[index]
    attrs = {key: sample.diagnostics[key] for key in (
        "msd_since_previous", "sweeps_since_previous", "acceptance", "contact_value",
        "reduced_pressure", "contact_measurements", "total_sweeps")}
    eq = result.equilibration
    attrs.update({
        "start": eq["start"],
        "equilibration_sweeps": eq["equilibration_sweeps"],
        "compression_sweeps": eq["compression_sweeps"],
        "equilibration_msd": eq["equilibration_msd"],
        "step_over_diameter": eq["step"] / result.diameter,
        "sample_interval_sweeps": eq["sample_interval_sweeps"],
        "chain_acceptance": eq["acceptance"],
        "n_particles": len(sample.positions),
        "phi_particles": result.phi,
    })
    return {key: (int(v) if isinstance(v, (bool, np.bool_)) else v) for key, v in attrs.items()}


def contact_histogram_dataset(result: ChainResult, index: int, settings: MCSettings):
    """The pair counts near contact accumulated since the previous sample (re-fittable).

    Parameters
    ----------
    result : ChainResult
        The finished chain.
    index : int
        Sample index in ``result.samples``.
    settings : MCSettings
        Supplies ``contact_range`` and ``contact_bins`` (the bin edges).

    Returns
    -------
    xarray.Dataset
        ``contact_pairs`` (contact_bin,) int64 counts, with coords ``contact_r_lower`` and
        ``contact_r_upper`` (bin edges r / D).
    """
    import xarray as xr

    edges = 1.0 + np.linspace(0.0, settings.contact_range, settings.contact_bins + 1)
    return xr.Dataset(
        {"contact_pairs": (("contact_bin",), result.samples[index].contact_histogram.astype(np.int64),
                           {"units": "1", "long_name": "pair counts with r in the bin, summed over "
                            "the contact measurements since the previous sample (attr "
                            "contact_measurements)"})},
        coords={"contact_r_lower": (("contact_bin",), edges[:-1],
                                    {"units": "D", "long_name": "lower bin edge r / D"}),
                "contact_r_upper": (("contact_bin",), edges[1:],
                                    {"units": "D", "long_name": "upper bin edge r / D"})},
    )
