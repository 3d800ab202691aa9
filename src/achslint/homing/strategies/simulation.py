"""Simulated drive (P-AXIS-00020 = 4, §3.4): one phase over the simulated distance to the zero pulse."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...axis.drives import DriveType
from ...catalogue.units import describe
from ..base import NEGATIVE, POSITIVE, Phase, StrategyDef, Use
from ..parameters import CNC_MOVES, SEQUENCE
from ..sequences import simulated

if TYPE_CHECKING:
    from ..setup import HomingSetup


def _phases(setup: HomingSetup) -> list[Phase]:
    distance = setup.axis.get("antr.simu.rpf_weg_bis_nip")
    unit = setup.axis.parameter("antr.simu.rpf_weg_bis_nip").unit(setup.axis_type)
    return [
        Phase(
            "to the simulated zero pulse",
            POSITIVE if setup.direction > 0 else NEGATIVE,
            setup.stage("vb_reflow"),
            setup.speed("vb_reflow"),
            f"the simulated zero pulse after rpf_weg_bis_nip = {describe(distance, unit)}",
            "the manual does not name the speed of this phase; vb_reflow is assumed",
        )
    ]


STRATEGY = StrategyDef(
    id="simulation",
    title="simulated drive: single phase",
    controlled_by="cnc",
    matches=lambda axis: axis.drive_type == DriveType.SIMULATION,
    describe=lambda axis: (
        "The drive is simulated: homing runs in one phase without a cam and sets the reference after the simulated "
        "distance to the zero pulse (rpf_weg_bis_nip); apart from it the sequence parameters are not used (§3.4)."
    ),
    parameters={
        **CNC_MOVES,
        "antr.simu.rpf_weg_bis_nip": Use("distance to the simulated zero pulse (§3.4)"),
        "kenngr.ref_richt": Use(
            "direction of the simulated move (assumed: the manual names only rpf_weg_bis_nip)"
        ),
        "getriebe[i].vb_reflow": Use(
            "speed of the simulated move (assumed: the manual names only rpf_weg_bis_nip)"
        ),
        "getriebe[i].a_ref": SEQUENCE["getriebe[i].a_ref"],  # P-AXIS-00285 lists the simulation drive
        "getriebe[i].tr_ref": SEQUENCE["getriebe[i].tr_ref"],
        "kenngr.ref_ohne_rev": Use(
            "a simulated spindle must home without reversal (§3.1.1.1)",
            when=lambda axis: axis.axis_type == "S",
            otherwise="simulated linear and rotary axes always home in one phase (§3.4)",
        ),
    },
    example="kenngr.antr_typ 4\nantr.simu.rpf_weg_bis_nip 200\n",
    phases=_phases,
    with_zero_pulse=True,
    one_phase=True,
    reference_speed="vb_reflow",
    unused="simulated drives home in one phase over rpf_weg_bis_nip; the other homing parameters are ignored (§3.4)",
    simulate=simulated.run,
)
