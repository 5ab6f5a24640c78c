"""Constants of a hard-particle Monte Carlo chain, and the error a chain raises."""

from __future__ import annotations

from dataclasses import dataclass

from randmedia.generate import refuse_invalid


class ChainError(RuntimeError):
    """The chain could not be started or did not behave (overlap, stalled compression)."""


@dataclass(frozen=True, kw_only=True)
class MCSettings:
    """Constants of a chain (:mod:`~randmedia.generate.hard_particles.chain`, contact fit:
    :mod:`~randmedia.generate.hard_particles.contact`); MSDs in units of D^2.

    The defaults are those of the config sections ``debye2020.hard_disks.mc`` and
    ``mrj2016.equilibrium.mc`` (schema ``workflow/schemas/hard_particles.mc.schema.yaml``);
    ``sample_msd``, ``measure_every``, ``contact_range`` and ``contact_order``, which the two
    set differently, have none (tests/test_defaults.py)."""

    target_acceptance: float = 0.25
    equilibration_msd: float = 4.0
    min_equilibration_sweeps: int = 200
    sample_msd: float
    interval_safety: float = 1.25
    block_sweeps: int = 10
    measure_every: int
    contact_range: float
    contact_bins: int = 20
    contact_order: int

    def __post_init__(self):
        checks = {
            "target_acceptance": 0.0 < self.target_acceptance < 1.0,
            "equilibration_msd": self.equilibration_msd >= 0.0,
            "min_equilibration_sweeps": self.min_equilibration_sweeps >= 0,
            "sample_msd": self.sample_msd > 0.0,
            "interval_safety": self.interval_safety >= 1.0,
            "block_sweeps": self.block_sweeps >= 1,
            "measure_every": self.measure_every >= 1,
            "contact_range": 0.0 < self.contact_range <= 0.5,
            "contact_bins": self.contact_bins >= self.contact_order + 2,
            "contact_order": 0 <= self.contact_order <= 4,
        }
        refuse_invalid("Monte Carlo settings", checks, self)

