"""Reading the TOML files achslint uses (configuration and dry-run scenarios)."""

from __future__ import annotations

import re
import sys
from pathlib import Path
from typing import Any

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib


def read_toml(path: Path, what: str, error: type[Exception]) -> dict[str, Any]:
    """The parsed file; any problem becomes `error` with a one-line message naming the file (and, for
    broken TOML, the line and column as `file:line:col:`, which editors and terminals can jump to).

    Read like every other file: a regular file only (never a FIFO or a device, never blocking), at most
    `files.SETTINGS_LIMIT` bytes."""
    from .files import SETTINGS_LIMIT, Refused, read_list, reason

    text = ""
    try:
        text = read_list(path, limit=SETTINGS_LIMIT, what=f"a {what}").decode("utf-8")
        return tomllib.loads(text)
    except Refused as exc:
        raise error(f"{what} {exc}") from None
    except OSError as exc:
        raise error(f"cannot read {what} {path}: {reason(exc)}") from None
    except UnicodeDecodeError as exc:
        raise error(f"{path}: {what} is not UTF-8 text (byte {exc.start + 1}); save it as UTF-8") from None
    except tomllib.TOMLDecodeError as exc:
        raise error(toml_error(path, what, exc, text)) from None
    except RecursionError:  # tomllib reads nested arrays and inline tables recursively
        raise error(
            f"{path}: {what} nests arrays or inline tables too deeply to be read (hundreds of levels); fix the file"
        ) from None


def toml_error(path: Path, what: str, exc: Exception, document: str) -> str:
    """`file:line:col: <what> is not valid TOML: <reason>` from a TOMLDecodeError."""
    text = str(exc)
    line, column = getattr(exc, "lineno", None), getattr(exc, "colno", None)
    where = re.search(r"\(at line (\d+), column (\d+)\)", text)
    if where:
        line, column = line or int(where.group(1)), column or int(where.group(2))
        text = text[: where.start()].rstrip()
    elif line is None and "end of document" in text:
        line, column = document.count("\n") + 1, 1
    position = f":{line}:{column}" if line else ""
    text = getattr(exc, "msg", None) or text
    return f"{path}{position}: {what} is not valid TOML: {text}; fix the file"
