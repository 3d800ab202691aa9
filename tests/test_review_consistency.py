"""Review: lint, explain and the dry-run tell one story about an axis.

Each test sets up one configuration on disk and asks the real CLI what the rules, `explain` and the dry-run
say of it: no finding may state a consequence the dry-run contradicts, and the dry-run may not run what a
finding says the CNC cannot do.
"""

from __future__ import annotations

import json
from pathlib import Path

HEAD = """kopf.achs_nr                        1
kopf.log_achs_name                  X
kenngr.achs_mode                    0x1
kenngr.achs_typ                     1
getriebe[0].a_ref                   500
"""


def write(folder: Path, body: str, name: str = "achsmds1.lis") -> Path:
    path = folder / name
    path.write_text(HEAD + body + "Ende\n", encoding="latin-1")
    return path


def codes(cli, path: Path) -> dict[str, str]:
    """The codes of the list's findings with their severities."""
    result = cli("lint", str(path), "--format", "json", "--exit-zero")
    return {d["code"]: d["severity"] for d in json.loads(result.stdout)["diagnostics"]}


def dry(cli, path: Path, *extra: str) -> dict:
    result = cli("dry-run", str(path), "--format", "json", *extra)
    assert result.stdout, result.stderr
    return json.loads(result.stdout)


# -- LIS322: a SERCOS zero pulse nobody latches is never found --------------------------------------------------

SERCOS_UNLATCHED = """kenngr.antr_typ                     2
kenngr.homing.homing_type           CNC_CONTROLLED
kenngr.homing_without_zero_pulse    0
"""


def test_sercos_zero_pulse_without_latch_does_not_home_in_the_dry_run(cli, tmp_path):
    """LIS322 (error) says the zero pulse of this SERCOS axis is never found (TF5200 §2.2, §3.1.1.2); the dry-run
    assumed a hardware latch and homed it on the zero pulse all the same."""
    path = write(tmp_path, SERCOS_UNLATCHED)
    assert codes(cli, path).get("LIS322") == "error"
    run = dry(cli, path)
    assert run["outcome"] == "failed"
    assert "LIS322" in run["failure"]
    assert run["reference"] is None


def test_sercos_zero_pulse_without_latch_one_phase_and_without_cam_fail_too(cli, tmp_path):
    for extra in ("kenngr.ref_ohne_rev 1\n", "kenngr.ref_ohne_rev 1\nkenngr.ref_ohne_nocken 1\n"):
        path = write(tmp_path, SERCOS_UNLATCHED + extra)
        assert codes(cli, path).get("LIS322") == "error", extra
        run = dry(cli, path)
        assert run["outcome"] == "failed", extra
        assert "LIS322" in run["failure"], extra


def test_sercos_zero_pulse_with_a_latch_still_homes(cli, tmp_path):
    for latch in (
        "antr.sercos.drive_supports_cnc_homing 1\nantr.cnc_homing_encoder 1\nantr.sercos.cnc_homing_rt_bit_layout 16\n",
        "kenngr.echtzeit_bit_nr 1\n",
    ):
        path = write(tmp_path, SERCOS_UNLATCHED + latch)
        assert "LIS322" not in codes(cli, path), latch
        assert dry(cli, path)["outcome"] == "homed", latch
