"""
What
----
A TwinCAT axis (`<IsgAxisDef>` in a tree-item or project XML file) whose
`<DriveType>` differs from `kenngr.antr_typ` in its embedded axis list
(`<AchsMds>`), or whose `<Spindle>` flag does not match `kenngr.achs_typ`
(4 = spindle).

Why
---
TwinCAT configures the drive interface and the channel from the tree item,
the CNC kernel from the list. When they disagree, the axis is wired as one
drive type and parameterised as another — homing type, telegram and drive
checks then follow the wrong drive.

Example
-------
```
<!-- file: Axis_Z.xti -->
<TreeItem><ItemName>Axis_Z</ItemName>
<IsgAxisDef><DriveType>2</DriveType><Spindle>false</Spindle>
<AchsMds><![CDATA[
kopf.achs_nr         3
kenngr.antr_typ      4          ( simulation, but the tree item says 2, SERCOS
Ende
]]></AchsMds></IsgAxisDef></TreeItem>
```

Use instead
-----------
The same drive type in both places, and `kenngr.achs_typ 4` exactly when
`<Spindle>true</Spindle>`:

```
<!-- file: Axis_Z.xti -->
<TreeItem><ItemName>Axis_Z</ItemName>
<IsgAxisDef><DriveType>2</DriveType><Spindle>false</Spindle>
<AchsMds><![CDATA[
kopf.achs_nr         3
kenngr.antr_typ      2          ( SERCOS, as in the tree item
Ende
]]></AchsMds></IsgAxisDef></TreeItem>
```

Reference
---------
TwinCAT 3 CNC axis tree item (IsgAxisDef: DriveType, Spindle, AchsMds); P-AXIS-00020, P-AXIS-00018.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..core.diagnostics import Diagnostic
    from .context import Context

CODE = "LIS505"
NAME = "xml-axis-definition"
FIX = "none"
PARAMETERS = ("kenngr.antr_typ", "kenngr.achs_typ")  # parameters this rule reads
SUMMARY = "TwinCAT axis definition (DriveType, Spindle) disagrees with the axis list"


def check(ctx: Context) -> Iterator[Diagnostic]:
    embedded = ctx.embedded
    if embedded is None:
        return  # not a list from an XML file
    values = ctx.values
    if (
        embedded.drive_type is not None
        and values.is_set("kenngr.antr_typ")
        and values.drive_type != embedded.drive_type
    ):
        yield ctx.cross(
            CODE,
            f"the TwinCAT axis says <DriveType>{embedded.drive_type}</DriveType> (line {embedded.drive_type_line}, "
            f"{values.drive_name(embedded.drive_type)}) but the list sets kenngr.antr_typ {values.drive_type} "
            f"({values.drive_name()}); make them the same",
            ["kenngr.antr_typ"],
        )
    if (
        embedded.spindle is not None
        and values.is_set("kenngr.achs_typ")
        and (values.axis_type == "S") != embedded.spindle
    ):
        kind = "a spindle" if values.axis_type == "S" else "a linear or rotary axis"
        yield ctx.cross(
            CODE,
            f"the TwinCAT axis says <Spindle>{'true' if embedded.spindle else 'false'}</Spindle> "
            f"(line {embedded.spindle_line}) but kenngr.achs_typ makes it {kind}; make them agree",
            ["kenngr.achs_typ"],
        )
