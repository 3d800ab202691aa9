"""Which lists a run reads, and which machine each list belongs to.

The one place that turns paths into lists and machines: `achslint lint`, the Python API and the language
server all ask a `Finder`. The editor passes nothing else: it reads the members' texts from its open
buffers itself, but which files form a machine is decided here, so the editor and the command line see
the same machine.

A machine is what the CNC loads together:
- every start-up list is one machine: the axis lists its `achs_mds[i]` entries name, with the default list
  of `default_achs_mds` underneath each of them. The start-up lists taken into account for a list are those
  named or found in a linted folder, and those in the list's own folder or the folder above it (the SDK
  keeps `hochlauf.lis` in `listen/`, or in `listen/ExtSchedule/`). Two start-up lists side by side (a CoE
  and an SoE variant of one machine) are two machines: their lists are never compared with each other.
- a `[[machine]]` table of a list's configuration declares a machine too: the lists its patterns find (for
  a repository without its start-up list); lists no start-up list and no table names are compared with no
  other list;
- axis XML files of one folder that no start-up list names are the exports of one TwinCAT project: one
  machine.
An ISG list update (`achsmds1-Update.xml`, `achsmds1-Revert.xml`, or any list in a folder named `Update`)
changes some parameters of one axis list while the CNC runs: it is no axis of its own, so it belongs to no
machine, and it is linted with the list it updates underneath (found by name beside it or one folder up).
"""

from __future__ import annotations

import functools
import os
import re
from collections.abc import Callable, Iterable, Sequence
from contextvars import ContextVar
from dataclasses import dataclass, field, replace
from pathlib import Path

from ..catalogue.kinds import STARTUP, entry_kind, kind_of
from ..core.decode import UnreadableInput, unreadable
from ..core.files import (
    Scope,
    inside,
    is_folder,
    is_xml,
    links_held,
    not_a_list_file,
    read_list,
    real_path,
    reason,
    same_file,
    shown_path,
)
from ..machine.resolved import Machine
from ..machine.startup import Startup, StartupEntry, entry_index, is_startup_list, read_startup
from ..syntax.parser import parse_bytes
from .config import ConfigError, Overrides, ResolvedConfig, Settings, discover, load_file, matches_glob

# Files found in a folder that are skipped with a note rather than reported as unreadable.
SKIPPED_KINDS = (
    "a FIFO",
    "a device",
    "a socket",
    "a folder",
    "not a regular file",
    "a file of the operating system",
)


@dataclass(frozen=True)
class Target:
    """One list to lint: a path on disk, or standard input under a display name."""

    name: str
    path: Path | None
    config: ResolvedConfig
    # The machines the list belongs to (the path of each start-up list naming it, else its folder): lists
    # sharing a key are checked together by the machine-level rules (LIS5xx).
    machines: tuple[str, ...] = ()
    defaults: Path | None = None  # default axis list loaded underneath (from a start-up list)
    # Whether fmt and --fix may rewrite it: it was named, found under a named folder, or lies in the folder of
    # the start-up list that named it (or below). A list a start-up list reaches in another folder is checked,
    # not rewritten (unless --follow-startup).
    writable: bool = True
    # The list's kind as a start-up list's entry names it ("axis", "default_axis"); None: told from the list.
    kind: str | None = None


@dataclass
class Discovery:
    """What the paths of a run come to."""

    targets: list[Target] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)  # exit code 2: something named or found could not be read
    notes: list[str] = field(default_factory=list)  # skipped on purpose; the run goes on
    # Lists of the same machine as a linted list, read only for the machine-level rules (their findings
    # are not reported): pre-commit passes the changed lists alone, their neighbours still count.
    context: list[Target] = field(default_factory=list)
    # The start-up lists of the run's machines; `reported` are those named or found in a linted folder
    # (their own findings are reported), the others were found beside a linted list.
    startups: list[Startup] = field(default_factory=list)
    reported: set[str] = field(default_factory=set)
    # start-up lists found in linted folders whose configuration names homing programs
    program_startups: list[Path] = field(default_factory=list)
    # named paths (and standard input, by its --stdin-filename) --force-exclude left out on purpose
    excluded: list[str] = field(default_factory=list)
    _seen: dict[object, tuple[list[Target], int]] = field(default_factory=dict)

    def add(self, target: Target, *, context: bool = False) -> None:
        """Take a target unless the same file is already taken (named twice, a folder and a file in it, a list
        two start-up lists name); a file reached again joins the machines it was reached through."""
        where = self.context if context else self.targets
        if target.path is None:
            where.append(target)
            return
        key = _identity(target.path)
        if key not in self._seen:
            self._seen[key] = (where, len(where))
            where.append(target)
            return
        taken, index = self._seen[key]
        before = taken[index]
        machines = tuple(dict.fromkeys([*before.machines, *target.machines]))
        if machines != before.machines:
            taken[index] = replace(before, machines=machines, defaults=before.defaults or target.defaults)

    def members(self, targets: Sequence[Target]) -> None:
        """Take the members of machines (`Finder.member_targets`) as context."""
        for target in targets:
            self.add(target, context=True)


def _identity(path: Path) -> object:
    if _LOOKED_AT.get() is not None:  # in a run: the (device, inode) looked up for the machines already
        return _file_id(path) or os.path.abspath(path)
    try:
        info = os.stat(path)
        return (info.st_dev, info.st_ino)
    except (OSError, ValueError):
        return os.path.abspath(path)


# By (device, inode): the start-up lists naming a file, each with the kinds it names the file as.
_Named = dict[tuple[int, int], list[tuple[Startup, list[str]]]]


class _LookedAt:
    """What `Finder.find` looks up once per run: the (device, inode) of each path it compares (None: it
    cannot be looked at), the files each start-up list names, and each path's configuration. A folder lint compares every list with
    every entry of every start-up list of the run (half a million comparisons for the fixtures), and the
    files of one run do not move under it. Outside a run (the editor asks for one list's machines) each
    question looks again."""

    def __init__(self) -> None:
        self.files: dict[Path, tuple[int, int] | None] = {}
        # by the id of the start-up list: the list (kept, so that its id stays its own) and `_kinds_named`
        self.named: dict[int, tuple[Startup, dict[tuple[int, int], list[str]]]] = {}
        self.configs: dict[Path, ResolvedConfig] = {}  # the configuration of each path (`Finder.config_for`)
        # by the id of the start-up list: the list and its absolute path (`_unique` asks it for every list)
        self.where: dict[int, tuple[Startup, str]] = {}
        # `Finder._naming` by folder (as given) and the sequence of start-up lists known (kept, so that its id stays its
        # own; `find` passes one for all its lists)
        self.naming: dict[tuple[str, int, int], tuple[Sequence[Startup], tuple[list[Startup], _Named]]] = {}
        # the lists of a folder by its absolute path (`_folder_machine`, asked for each XML file in it)
        self.folders: dict[str, list[Path]] = {}
        # the machine of each start-up list, by the list's id (kept, so that its id stays its own): what
        # `find` asks of it (its key, files, default list) is read, never changed
        self.machines: dict[int, tuple[Startup, Machine]] = {}
        # git's answers (`_not_ignored_by_git`): the folder asked from, the files asked about (absolute) and
        # those it ignores
        self.git: list[tuple[Path, frozenset[str], frozenset[str]]] = []
        # whether a file's content makes it a start-up list (`is_startup`): each file is sniffed once a run,
        # though it is asked about as a list, as a neighbour of every list of its folder and of the one below
        self.sniffed: dict[Path, bool] = {}
        # the files of a folder that are start-up lists, by the folder as given (`startups_around` asks
        # for a folder and the folder above it; neighbouring folders share the one above); None: unreadable
        self.places: dict[str, list[Path] | None] = {}
        # `_naming` for the start-up lists known to `find` alone, by their sequence's id (kept, so that its
        # id stays its own): each folder adds only the start-up lists around it that are not among them
        self.known: dict[
            tuple[int, int], tuple[Sequence[Startup], tuple[list[Startup], _Named, set[str]]]
        ] = {}
        # the (device, inode) of a sequence of files by its id (kept, so that its id stays its own): the axis
        # lists of a folder's start-up lists, the files of a `[[machine]]` table
        self.identities: dict[int, tuple[object, frozenset[tuple[int, int]]]] = {}


_LOOKED_AT: ContextVar[_LookedAt | None] = ContextVar("looked_at", default=None)


def _looking_once(find: Callable[[Finder, list[str]], Discovery]) -> Callable[[Finder, list[str]], Discovery]:
    @functools.wraps(find)
    def run(finder: Finder, paths: list[str]) -> Discovery:
        token = _LOOKED_AT.set(_LookedAt())
        try:
            with links_held():
                return find(finder, paths)
        finally:
            _LOOKED_AT.reset(token)

    return run


@dataclass
class Finder:
    """Finds lists and machines with the settings of one run (the command line's or the editor's)."""

    overrides: Overrides = field(default_factory=Overrides)
    config_file: str | None = None  # --config: this file for every list instead of the nearest one
    stdin_filename: str | None = None
    force_exclude: bool = False  # exclude patterns apply to named files too
    respect_gitignore: bool = True
    follow_startup: bool = False  # the lists a named start-up list reaches may be rewritten too
    # Whether the machine-level rules run for a named list (only then are its neighbours read).
    machine_rules: Callable[[Path], bool] = lambda path: True
    lenient: bool = False  # a broken configuration counts as none (the editor says so once, elsewhere)
    _fixed: ResolvedConfig | None = None
    _startups: dict[str, Startup | None] = field(default_factory=dict)  # by absolute path
    _around: dict[str, list[Startup]] = field(default_factory=dict)  # by folder
    _tables: dict[str, list[Machine]] = field(default_factory=dict)  # [[machine]] tables by config file

    def __post_init__(self) -> None:
        self._fixed = load_file(Path(self.config_file)) if self.config_file else None

    def config_for(self, path: Path) -> ResolvedConfig:
        """The configuration of a file. Raises `ConfigError`, except for the editor (`lenient`), which shows
        a broken configuration once and goes on with the defaults."""
        if self._fixed is not None:
            return self._fixed
        looked = _LOOKED_AT.get()
        if looked is not None and path in looked.configs:
            return looked.configs[path]
        try:
            config = discover(path)
        except ConfigError:
            if self.lenient:
                return ResolvedConfig(Settings())
            raise
        if looked is not None:
            looked.configs[path] = config
        return config

    # -- start-up lists ----------------------------------------------------------------------------------
    def startup(self, path: Path, scope: Scope | None = None) -> Startup:
        """A start-up list read with the CNC root of the run (`--cnc-root`, else the configuration's, else
        its default). Raises `OSError` / `UnreadableInput`."""
        key = os.path.abspath(path)
        known = self._startups.get(key)
        if known is not None:
            return known
        config = self.config_for(path)
        root: Path | None
        if self.overrides.cnc_root is not None:
            root, origin = Path(self.overrides.cnc_root), "given by --cnc-root"
        else:
            root, origin = config.cnc_root(), f"set by `cnc-root` in {config.path}"
        startup = read_startup(path, scope, root, origin)
        self._startups[key] = startup
        return startup

    def startups_around(self, folder: Path) -> list[Startup]:
        """The start-up lists in a folder and the folder above it that can be read (the others are the
        business of a run that names them)."""
        key = os.path.abspath(folder)
        if key not in self._around:
            found: list[Startup] = []
            for place in (folder, folder.parent):
                candidates = _startup_files_in(place)
                if candidates is None:
                    continue
                for candidate in candidates:
                    if not_a_list_file(candidate) is not None:
                        continue
                    try:
                        found.append(self.startup(candidate))
                    except (OSError, UnreadableInput):
                        continue
            self._around[key] = found
        return self._around[key]

    # -- machines ------------------------------------------------------------------------------------------
    def machines_of(self, path: Path, known: Sequence[Startup] = ()) -> list[Machine]:
        """The machines a list belongs to (see the module's description): every start-up list (of `known`, or
        beside the list) and every `[[machine]]` table of its configuration that names it; else, for axis XML,
        the XML files of its folder. A start-up list is a machine of its own. Nothing for a list that is no
        member of any machine: it is compared with no other list."""
        if is_startup(path):  # by its name, or by its content (a start-up list named otherwise)
            try:
                startup = self.startup(path)
            except (OSError, UnreadableInput):
                return []
            return [_machine_of(startup)]
        if is_list_update(path):
            return []  # it changes one list; it is no axis of its own
        startups, index = self._naming(path.parent, known)
        identity = _file_id(path)
        naming = [s for s, kinds in index.get(identity, ()) if _loads(kinds)] if identity is not None else []
        declared = [m for m in self._declared(path) if identity is not None and _among(identity, m, m.files)]
        if naming or declared:
            return [*(_machine_of(startup) for startup in naming), *declared]
        if is_xml(path.name):
            folder = self._folder_machine(path.parent, startups)
            if any(same_file(f, path) for f in folder.files):
                return [folder]
        return []

    def _naming(self, folder: Path, known: Sequence[Startup]) -> tuple[list[Startup], _Named]:
        """The start-up lists a list in `folder` may belong to (`known` and those around the folder, each
        once), and by (device, inode) the files they name, each with the start-up lists naming it and the
        kinds each names it as, in the start-up lists' order. Made once per folder in a run: a folder lint
        asks it for every list, of every start-up list of the run."""
        looked = _LOOKED_AT.get()
        key = (str(folder), id(known), len(known))  # the folder as given: the same answer however spelt
        if looked is not None and key in looked.naming and looked.naming[key][0] is known:
            return looked.naming[key][1]
        around = self.startups_around(folder)
        if looked is None:
            startups = _unique([*known, *around])
            index = _index(startups)
        else:
            # `known` first, then those around the folder that are not known: the index of `known` is made
            # once a run, and each folder adds the few of its own (most folders have none to add)
            startups, index, where = _known_index(known, looked)
            extra = [s for s in _unique(around) if _where(s) not in where]
            if extra:
                startups, index = [*startups, *extra], dict(index)
                for identity, named in _index(extra).items():
                    index[identity] = [*index.get(identity, ()), *named]
            looked.naming[key] = (known, (startups, index))
        return startups, index

    def _declared(self, path: Path) -> list[Machine]:
        """The machines the `[[machine]]` tables of a list's configuration declare."""
        config = self.config_for(path)
        key = str(config.path)
        if key not in self._tables:
            self._tables[key] = [
                Machine(
                    name,
                    files=[
                        f
                        for f in files
                        if not self._excluded(config, f)
                        and not_a_list_file(f) is None
                        and not is_startup_list(f)
                        and not is_list_update(f)  # an update changes one list: no member of its own
                    ],
                )
                for name, files in config.declared_machines()
            ]
        return self._tables[key]

    def _folder_machine(self, folder: Path, startups: list[Startup]) -> Machine:
        """The axis XML files of a folder that no start-up list names: the exports of one TwinCAT project."""
        looked = _LOOKED_AT.get()
        key = os.path.abspath(folder)
        if looked is not None and key in looked.folders:
            lists = looked.folders[key]
        else:
            lists, _ = self._walk(
                folder, Scope.of([str(folder)]), Discovery(), recursive=False, only_xml=True
            )
            if looked is not None:
                looked.folders[key] = lists
        members = [
            path
            for path in lists
            if is_xml(path.name) and not is_list_update(path) and not _named_by(startups, path)
        ]
        return Machine(str(folder), files=members)

    def member_targets(self, machines: Sequence[Machine]) -> list[Target]:
        """The axis lists of machines as lists to read (for the machine-level rules), in the machines' order;
        a start-up list's with the default list it loads underneath."""
        return [
            Target(
                shown_path(f),
                f,
                self.config_for(f),
                (machine.key,),
                machine.defaults,
                kind="axis" if machine.startup is not None else None,
            )
            for machine in machines
            for f in machine.files
        ]

    def default_list_of(self, path: Path) -> tuple[Path, Path] | None:
        """(default axis list, start-up list) when a start-up list that names an axis list (found as for lint:
        named by the run or beside the list) loads a default axis list under it, as the CNC does; the first
        such start-up list when several name the list. None for a list no start-up list names."""
        for machine in self.machines_of(path):
            if machine.defaults is not None and machine.startup is not None and not is_startup(path):
                return machine.defaults, machine.startup.path
        return None

    # -- a run's paths -------------------------------------------------------------------------------------
    @_looking_once
    def find(self, paths: list[str]) -> Discovery:
        """Expand folders by the include/exclude globs and start-up lists by their entries; named files are
        always linted. Each file is taken once, however often it is reached; each list is put in the
        machines it belongs to (see the module's description)."""
        found = Discovery()
        scope = Scope.of(paths)
        # (name shown, path) of every list: named, found in a folder, or reached through a start-up list
        lists: list[tuple[str, Path]] = []
        named: list[Path] = []
        for raw in paths:
            if raw == "-":
                name = self.stdin_filename or "<stdin>"
                config = self.config_for(Path(name) if self.stdin_filename else Path.cwd())
                if self.stdin_filename and self.force_exclude and self._excluded(config, Path(name)):
                    found.excluded.append(raw)  # as ruff: the name the editor gives it is excluded
                    continue
                found.add(Target(name, None, config))
                continue
            path = Path(raw)
            if is_folder(path):
                walked, startups = self._walk(path, scope, found)
                lists += [(str(file), file) for file in walked]
                for startup_path in startups:
                    lists += self._take_startup(startup_path, scope, found, named=False)
                continue
            problem = not_a_list_file(path)
            if problem is None and self.force_exclude and self._excluded(self.config_for(path), path):
                found.excluded.append(raw)
                continue
            if problem is not None:
                found.errors.append(f"{raw}: {problem}")
            elif is_startup(path):
                self._take_startup(path, scope, found, named=True)
            else:
                lists.append((raw, path))
                named.append(path)
        known = list(found.startups)
        for name, path in lists:
            if is_list_update(path):
                base = updated_list(path)
                if base is None:
                    found.notes.append(
                        f"{name}: a list update; the list it changes was not found beside it, so it is "
                        "checked alone"
                    )
                found.add(Target(name, path, self.config_for(path), (), base))
                continue
            kind = self.entry_kind(path, known)
            # every kind belongs to the machines that name it (a channel list's cross-list findings are its own)
            machines = self.machines_of(path, known)
            keys = tuple(m.key for m in machines)  # none: compared with no other list
            defaults = loaded_under(kind, machines)
            found.add(Target(name, path, self.config_for(path), keys, defaults, kind=kind))
            self._remember(machines, found)
        for path in named:  # the other members of its machines, for the machine-level rules
            if self.machine_rules(path):
                found.members(self.member_targets(self.machines_of(path, known)))
        return found

    def entry_kind(self, path: Path, known: Sequence[Startup] = ()) -> str | None:
        """The kind of list a start-up list (of the run, or beside the list) names it as: `achs_mds[i]` an
        axis list, `default_achs_mds` the default axis list, `sda_mds[i]` / `default_sda_mds` a (default)
        channel list, `rtconf_lis` the real-time configuration and so on (`catalogue.kinds.ENTRY_KINDS`);
        None when no start-up list names it (its content tells)."""
        kinds: list[str] = []
        identity = _file_id(path)
        if identity is not None:
            for _, named in self._naming(path.parent, known)[1].get(identity, ()):
                kinds += named
        # Start-up lists that disagree (an old variant naming an axis list as a channel list): an axis list
        # of a machine stays one, so no axis rule is switched off by another file's entry.
        for preferred in ("axis", "default_axis"):
            if preferred in kinds:
                return preferred
        return kinds[0] if kinds else None

    def _remember(self, machines: list[Machine], found: Discovery) -> None:
        for machine in machines:
            if machine.startup is not None and all(s is not machine.startup for s in found.startups):
                found.startups.append(machine.startup)

    def _take_startup(
        self, path: Path, scope: Scope, found: Discovery, *, named: bool
    ) -> list[tuple[str, Path]]:
        """A start-up list named, or found in a linted folder: a machine whose own findings are reported.
        Named, its axis lists are linted as its members; found in a folder, those inside the linted paths
        are returned to be linted with every machine they belong to, those outside are read for the
        machine-level rules only."""
        try:
            startup = self.startup(path, scope)
        except OSError as exc:
            found.errors.append(f"cannot read {path}: {reason(exc)}")
            return []
        except UnreadableInput as exc:
            found.errors.append(f"{path}: {exc}")
            return []
        if all(s is not startup for s in found.startups):
            found.startups.append(startup)
        found.reported.add(str(startup.path))
        # It is a list of its own kind too: its lines are checked against the start-up catalogue, and fmt and
        # --fix may rewrite it (named, or found in a linted folder).
        name = str(startup.path)
        found.add(Target(name, startup.path, self.config_for(startup.path), (name,), kind=STARTUP.id))
        found_inside = []
        for member in self.member_targets([_machine_of(startup)]):
            assert member.path is not None  # members are files
            if named:
                # Its own folder counts as named with it; lists in other folders are only checked.
                mine = inside(member.path, Path(os.path.abspath(path)).parent) or scope.contains(member.path)
                found.add(replace(member, writable=self.follow_startup or mine))
            elif scope.contains(member.path) and not self._excluded(member.config, member.path):
                found_inside.append((member.name, member.path))
            else:
                found.add(member, context=True)
        # The lists of other kinds it names (its default list, channel lists, tool data, the real-time
        # configuration ...) are checked against their own catalogues: named with it, or in a linted folder.
        folder = Path(os.path.abspath(path)).parent
        for entry, kind in self._other_lists(startup):
            assert entry.path is not None
            if not named and (
                not scope.contains(entry.path) or self._excluded(self.config_for(entry.path), entry.path)
            ):
                continue
            mine = inside(entry.path, folder) or scope.contains(entry.path)
            target = Target(
                shown_path(entry.path), entry.path, self.config_for(entry.path), (str(startup.path),)
            )
            under = loaded_under(kind, [_machine_of(startup)])
            found.add(replace(target, writable=self.follow_startup or mine, kind=kind, defaults=under))
        return found_inside

    def _other_lists(self, startup: Startup) -> list[tuple[StartupEntry, str]]:
        """The lists besides its axis lists a start-up list names and achslint can read, with their kinds. One
        that cannot be read is left to LIS504 (default and channel lists) or said in a note by its lint."""
        named: list[tuple[StartupEntry | None, str | None]] = [
            (startup.default, "default_axis"),
            (startup.default_channel, "default_channel"),
            *((entry, "channel") for entry in startup.channels),
            *((entry, "compensation") for entry in startup.compensations),  # achs_kw[i], P-STUP-00017
            *((entry, other.id if (other := entry_kind(entry.key)) else None) for entry in startup.others),
        ]
        lists = []
        for entry, kind in named:
            if entry is None or entry.path is None or kind is None or _names(entry.path, startup.path):
                continue
            if is_xml(entry.path.name):
                continue  # XML lists of other kinds are not read yet
            # Readable as text (what LIS504 checks), not parsed here: the lint of the list parses it, in a
            # worker process when the run has several (parsing every list twice cost a machine of 30 other
            # lists a second of the main process).
            if not_a_list_file(entry.path) is not None or unreadable(entry.path) is not None:
                continue  # LIS504 says why (a default or channel list), the CNC too for the others
            lists.append((entry, kind))
        return lists

    def _walk(
        self, folder: Path, scope: Scope, found: Discovery, *, recursive: bool = True, only_xml: bool = False
    ) -> tuple[list[Path], list[Path]]:
        """The lists and start-up lists in a folder tree. A folder that cannot be read, or a list that
        cannot (a broken link, a loop), is an error: those could be lists nobody checked. FIFOs, devices and
        links that lead outside the paths given are skipped with a note: they are not lists of this project.
        `only_xml`: the other files are passed over (for a caller that keeps the XML lists alone; git is
        then asked about none of the others)."""
        lists: list[Path] = []
        startups: list[Path] = []

        def unreadable(exc: OSError) -> None:
            found.errors.append(f"cannot read folder {exc.filename}: {reason(exc)}")

        for root, dirs, files in os.walk(folder, onerror=unreadable):
            here = Path(root)
            # a folder its own configuration excludes is not searched (`exclude = ["archive"]`): nothing in
            # it is linted, so nothing in it is looked at or reported
            dirs[:] = (
                sorted(d for d in dirs if not d.startswith(".") and not self._pruned(here / d))
                if recursive
                else []
            )
            for name in dirs:  # os.walk does not enter linked folders; one that leads outside is said
                linked = here / name
                if os.path.islink(linked) and not scope.contains(linked):
                    found.notes.append(
                        f"{linked}: skipped, it links to {real_path(linked)}, outside the paths given"
                    )
            config = self.config_for(here / "x")
            settings = self.overrides.apply(config.settings)
            include, exclude = settings.include, settings.exclude
            for name in sorted(files):
                if only_xml and not is_xml(name):
                    continue
                path = here / name
                # a start-up list by its name, or (a `.lis` the include patterns do not take) by its content
                startup = is_startup_list(path) or (
                    path.suffix.lower() == ".lis" and not _included(name, include) and is_startup(path)
                )
                if startup and config.settings.homing_programs:
                    found.program_startups.append(path)  # its homing programs are checked too
                xml = is_xml(name)  # axis XML is found by content, whatever the export calls it
                if not xml and not startup and not _included(name, include):
                    continue
                if exclude and _excluded_by(config, path, exclude):
                    continue
                problem = not_a_list_file(path)
                if xml and problem is None and scope.contains(path) and not _axis_xml(path, found):
                    continue
                if problem is None and not scope.contains(path):
                    found.notes.append(
                        f"{path}: skipped, it links to {real_path(path)}, outside the paths given"
                    )
                elif problem is not None and problem.startswith(SKIPPED_KINDS):
                    found.notes.append(f"{path}: skipped, it is {problem}")
                elif problem is not None:
                    found.errors.append(f"cannot read {path}: {problem}")
                else:
                    (startups if startup else lists).append(path)
        if self.respect_gitignore:  # one question to git for both
            kept = set(_not_ignored_by_git(folder, [*lists, *startups]))
            lists, startups = [p for p in lists if p in kept], [p for p in startups if p in kept]
        return lists, startups

    def _excluded(self, config: ResolvedConfig, path: Path) -> bool:
        return _excluded_by(config, path, self.overrides.apply(config.settings).exclude)

    def _pruned(self, folder: Path) -> bool:
        """Whether a folder found in a walk is excluded by the configuration of the files in it."""
        config = self.config_for(folder / "x")
        exclude = self.overrides.apply(config.settings).exclude
        return bool(exclude) and _excluded_by(config, folder, [_folder_form(p) for p in exclude])


def _folder_form(pattern: str) -> str:
    """An exclude pattern as it applies to a folder: `archive/*` (`*` crosses `/`) and `archive/**` take
    everything below `archive`, so they exclude the folder itself (still anchored where the pattern is)."""
    for tail in ("/**", "/*"):
        if pattern.endswith(tail) and pattern[: -len(tail)].strip("/"):
            head = pattern[: -len(tail)]
            return head if "/" in head else f"./{head}"
    return pattern


def _excluded_by(config: ResolvedConfig, path: Path, patterns: Sequence[str]) -> bool:
    return any(matches_glob(config.relative(path), pattern) for pattern in patterns)


HEAD_BYTES = 64 * 1024  # what is read of a named file to tell a start-up list by its content


def _may_be_startup(path: Path) -> bool:
    """A file that may hold a start-up list: named like one, or any `.lis` (its content then tells)."""
    return is_startup_list(path) or path.suffix.lower() == ".lis"


def _included(name: str, include: list[str]) -> bool:
    return any(matches_glob(name.lower(), pattern.lower()) for pattern in include)


def _startup_files_in(place: Path) -> list[Path] | None:
    """The files of a folder that are start-up lists (by name or content), sorted; None when the folder
    cannot be read. Looked at once per folder in a run."""
    looked = _LOOKED_AT.get()
    key = str(place)
    if looked is not None and key in looked.places:
        return looked.places[key]
    found: list[Path] | None
    try:
        found = sorted(p for p in place.iterdir() if _may_be_startup(p) and is_startup(p))
    except (OSError, ValueError):  # ValueError: a NUL in the name
        found = None
    if looked is not None:
        looked.places[key] = found
    return found


def is_startup(path: Path) -> bool:
    """A start-up list by its name (`hochlauf*.lis`, `startup*.lis`) or, named otherwise, by its content
    (`achs_mds[0]`, `zahl_mds` ...: `catalogue.kinds`), read from the head of the file (once per run)."""
    if is_startup_list(path):
        return True
    if is_xml(path.name):
        return False
    looked = _LOOKED_AT.get()
    if looked is None:
        return _startup_by_content(path)
    known = looked.sniffed.get(path)
    if known is None:
        known = looked.sniffed[path] = _startup_by_content(path)
    return known


def _startup_by_content(path: Path) -> bool:
    try:
        head = read_list(path, HEAD_BYTES)
    except OSError:
        return False  # the lint of the file says why
    if not _STARTUP_KEYS.search(head):  # no entry naming an axis list: no start-up list, nothing to parse
        return False
    try:
        file = parse_bytes(head, str(path))
    except UnreadableInput:
        return False
    # The start-up keys at the start of a line are clear evidence already: the content decides (no minimum
    # number of lines; a start-up list may name one axis list).
    return kind_of(file).id == STARTUP.id


def channel_loaded_by(path: Path) -> tuple[Path, int] | None:
    """The start-up list that loads `path` as one of its channels (an `sda_mds[i]` below `kanal_anzahl`) and
    that channel's number (i + 1), for `explain` of a channel list; None unless exactly one start-up list
    beside the list or in the folder above does."""
    found = {
        (startup.path, entry_index(entry) + 1)
        for startup in Finder().startups_around(path.parent)
        for entry in startup.loaded_channels()
        if entry.path is not None and same_file(entry.path, path)
    }
    return found.pop() if len(found) == 1 else None


# The keys only a start-up list has at the start of a line: a list without any is none (a cheap look at the
# bytes before the list is parsed, which every named axis list would otherwise pay for).
_STARTUP_KEYS = re.compile(rb"^[ \t]*(?:achs_mds\[|default_achs_mds|zahl_mds|sda_mds\[|kanal_anzahl)", re.M)


UPDATE_SUFFIXES = ("-update", "-revert", "_update", "_revert")
UPDATE_FOLDER = "update"


def is_list_update(path: Path) -> bool:
    """An ISG list update: `<list>-Update.xml` / `<list>-Revert.xml`, or any list in a folder `Update/`."""
    return path.stem.lower().endswith(UPDATE_SUFFIXES) or path.parent.name.lower() == UPDATE_FOLDER


def updated_list(path: Path) -> Path | None:
    """The list an update changes: the file of the update's name without its suffix (`achsmds1-Update.xml`
    -> `achsmds1.lis` or `achsmds1.xml`), beside it or in the folder above (`listen/Update/` -> `listen/`)."""
    stem = path.stem
    for suffix in UPDATE_SUFFIXES:
        if stem.lower().endswith(suffix):
            stem = stem[: -len(suffix)]
            break
    for folder in (path.parent, path.parent.parent):
        for suffix in (".lis", ".xml"):
            candidate = folder / f"{stem}{suffix}"
            if candidate != path and not is_list_update(candidate) and not_a_list_file(candidate) is None:
                return candidate
    return None


def loaded_under(kind: str | None, machines: Sequence[Machine]) -> Path | None:
    """The default list the CNC loads under a list of `kind` (None: told by its content, an axis list unless
    it says otherwise) of these machines: their default axis list under an axis list, their default channel
    list (`default_sda_mds`) under a channel list; none under the other kinds."""
    if kind in (None, "axis"):
        return next((m.defaults for m in machines if m.defaults is not None), None)
    if kind == "channel":
        for machine in machines:
            startup = machine.startup
            entry = startup.default_channel if startup is not None else None
            path = entry.path if entry is not None else None
            if startup is not None and path is not None and not same_file(path, startup.path):
                return path
    return None


def _names(entry: Path | None, path: Path) -> bool:
    if entry is None:
        return False
    one = _file_id(entry)
    return one is not None and one == _file_id(path)


def _file_id(path: Path) -> tuple[int, int] | None:
    """The (device, inode) of a file, links followed (as `same_file` compares them); None when it cannot be
    looked at."""
    looked = _LOOKED_AT.get()
    if looked is not None and path in looked.files:
        return looked.files[path]
    try:
        info = os.stat(path)
        identity: tuple[int, int] | None = (info.st_dev, info.st_ino)
    except (OSError, ValueError):
        identity = None
    if looked is not None:
        looked.files[path] = identity
    return identity


# The kinds of the lists a start-up list loads as the machine's: its default list, axis lists (up to `zahl_mds`)
# and channel lists; the others are tool data, zero offsets and so on.
_LOADED = ("default_axis", "axis", "default_channel", "channel")


def _loads(kinds: Sequence[str]) -> bool:
    return any(kind in _LOADED for kind in kinds)


def _kinds_named(startup: Startup) -> dict[tuple[int, int], list[str]]:
    """The files a start-up list names, by (device, inode), each with the kinds its entries name it as, in
    the order `Finder.entry_kind` weighs them: the default axis list, axis lists (up to `zahl_mds`), the
    default channel list, channel lists (each kind once), then tool data, zero offsets ... (per entry)."""
    looked = _LOOKED_AT.get()
    if looked is not None and id(startup) in looked.named:
        return looked.named[id(startup)][1]
    kinds: dict[tuple[int, int], list[str]] = {}
    groups: list[tuple[str, Sequence[StartupEntry | None]]] = [
        ("default_axis", [startup.default]),
        ("axis", startup.loaded_axes()),
        ("default_channel", [startup.default_channel]),
        ("channel", startup.channels),
    ]
    for kind, entries in groups:
        for identity in {_file_id(e.path) for e in entries if e is not None and e.path is not None}:
            if identity is not None:
                kinds.setdefault(identity, []).append(kind)
    for entry in startup.others:  # tool data, zero offsets, the real-time configuration ...
        other = entry_kind(entry.key)
        identity = _file_id(entry.path) if other is not None and entry.path is not None else None
        if other is not None and identity is not None:
            kinds.setdefault(identity, []).append(other.id)
    if looked is not None:
        looked.named[id(startup)] = (startup, kinds)
    return kinds


def _machine_of(startup: Startup) -> Machine:
    """`Machine.of(startup)`, made once a run (every list a start-up list names asks for it)."""
    looked = _LOOKED_AT.get()
    known = looked.machines.get(id(startup)) if looked is not None else None
    if known is not None and known[0] is startup:
        return known[1]
    machine = Machine.of(startup)
    if looked is not None:
        looked.machines[id(startup)] = (startup, machine)
    return machine


def _named_by(startups: list[Startup], path: Path) -> bool:
    """Whether an axis entry of one of `startups` names the file `path`."""
    identity = _file_id(path)
    return identity is not None and _among(identity, startups, (e.path for s in startups for e in s.axes))


def _among(identity: tuple[int, int], owner: object, files: Iterable[Path | None]) -> bool:
    """Whether one of `files` (those of `owner`) is the file of that (device, inode). In a run they are
    looked up once for `owner`, whose files do not change while the run lasts."""
    looked = _LOOKED_AT.get()
    known = looked.identities.get(id(owner)) if looked is not None else None
    if known is not None and known[0] is owner:
        return identity in known[1]
    identities = frozenset(i for i in (_file_id(f) for f in files if f is not None) if i is not None)
    if looked is not None:
        looked.identities[id(owner)] = (owner, identities)
    return identity in identities


def _index(startups: Sequence[Startup]) -> _Named:
    """By (device, inode): the start-up lists naming a file, each with the kinds it names the file as, in
    the order of `startups`."""
    index: _Named = {}
    for startup in startups:
        for identity, kinds in _kinds_named(startup).items():
            index.setdefault(identity, []).append((startup, kinds))
    return index


def _known_index(known: Sequence[Startup], looked: _LookedAt) -> tuple[list[Startup], _Named, set[str]]:
    """`known` each once, their `_index` and their absolute paths: made once a run for `find`'s start-up
    lists."""
    key = (id(known), len(known))
    made = looked.known.get(key)
    if made is not None and made[0] is known:
        return made[1]
    startups = _unique(list(known))
    answer = (startups, _index(startups), {_where(s) for s in startups})
    looked.known[key] = (known, answer)
    return answer


def _unique(startups: list[Startup]) -> list[Startup]:
    seen: set[str] = set()
    out = []
    for startup in startups:
        key = _where(startup)
        if key not in seen:
            seen.add(key)
            out.append(startup)
    return out


def _where(startup: Startup) -> str:
    """The absolute path of a start-up list, found once per run."""
    looked = _LOOKED_AT.get()
    known = looked.where.get(id(startup)) if looked is not None else None
    if known is not None and known[0] is startup:
        return known[1]
    where = os.path.abspath(startup.path)
    if looked is not None:
        looked.where[id(startup)] = (startup, where)
    return where


def _axis_xml(path: Path, found: Discovery) -> bool:
    """Whether an XML file found in a folder may hold lists (axis lists, a TwinCAT channel item); the others
    get a note."""
    from ..syntax.xmlinput import may_hold_list, root_element

    try:
        data = read_list(path)
    except OSError as exc:
        found.errors.append(f"cannot read {path}: {reason(exc)}")
        return False
    if may_hold_list(data):
        return True
    found.notes.append(f"{path}: skipped, an XML file without a list (<{root_element(data)}>)")
    return False


def startup_files(startup: Startup) -> list[Path]:
    """Every file a start-up list leads achslint to read: itself and the lists its entries name."""
    entries = [startup.default, startup.default_channel, *startup.axes, *startup.channels]
    return [startup.path, *(entry.path for entry in entries if entry is not None and entry.path is not None)]


def machine_files(startup: Path, cnc_root: Path | None = None, config_file: str | None = None) -> list[Path]:
    """The files a machine's start-up list leads achslint to read, with the configuration that applies to
    it (`config_file`, else the one found above it; its `cnc-root` unless `cnc_root` is given): for the
    check that a report or plot file is none of them. Nothing when the start-up list cannot be read (the
    run says so itself). Raises `ConfigError`."""
    config = load_file(Path(config_file)) if config_file else discover(startup)
    root = cnc_root or config.cnc_root()
    try:
        files = startup_files(read_startup(startup, None, root))
    except (OSError, UnreadableInput):
        return []
    return files + ([config.path] if config.path is not None else [])


def _not_ignored_by_git(folder: Path, files: list[Path]) -> list[Path]:
    """`files` without those git ignores (.gitignore, .git/info/exclude); all of them outside a git work tree
    or without git. In a run, git is not asked again about files it answered for a folder of the same work
    tree (the lists of a folder a machine of XML exports is made of, found by the folder lint already)."""
    import subprocess

    if not files or not _maybe_in_git_work_tree(folder):
        return files
    asked = [os.path.abspath(f) for f in files]
    looked = _LOOKED_AT.get()
    known = _answered_before(folder, asked, looked) if looked is not None else None
    if known is not None:
        return [f for f, name in zip(files, asked, strict=True) if name not in known] if known else files
    try:
        answer = subprocess.run(
            ["git", "-C", str(folder), "check-ignore", "--stdin", "-z"],
            input=b"\0".join(os.fsencode(name) for name in asked) + b"\0",
            capture_output=True,
            timeout=60,
            check=False,
        )
    except (OSError, subprocess.SubprocessError):
        return files
    if answer.returncode not in (0, 1):  # 0: some are ignored; 1: none is; 128: not a git work tree
        return files
    ignored = (
        {os.fsdecode(name) for name in answer.stdout.split(b"\0") if name}
        if answer.returncode == 0
        else set()
    )
    if looked is not None:
        looked.git.append((folder, frozenset(asked), frozenset(ignored)))
    if answer.returncode != 0:
        return files
    return [f for f, name in zip(files, asked, strict=True) if name not in ignored]


def _answered_before(folder: Path, asked: list[str], looked: _LookedAt) -> frozenset[str] | None:
    """Which of `asked` git ignores, when an earlier answer of the run covers them all and was given for a
    folder of the same work tree as `folder`; None when git must be asked."""
    if any(os.environ.get(name) for name in _WHERE_GIT_LOOKS):  # git told where to look: ask it each time
        return None
    for earlier, names, ignored in looked.git:
        if names.issuperset(asked) and _same_work_tree(real_path(earlier), real_path(folder)):
            return ignored
    return None


# What tells git where its repository is, or how far up to look for one.
_WHERE_GIT_LOOKS = ("GIT_DIR", "GIT_WORK_TREE", "GIT_COMMON_DIR", "GIT_CEILING_DIRECTORIES")


def _same_work_tree(top: Path, below: Path) -> bool:
    """Whether git, started in the resolved folder `below`, finds the repository it finds in the resolved
    folder `top`: `below` is `top` or lies under it, on the same file system (git stops at another one),
    with no `.git` of a repository of its own on the way up."""
    if not inside(below, top):
        return False
    try:
        device = os.stat(top).st_dev
        current = below
        while current != top:
            if os.path.lexists(current / ".git") or os.stat(current).st_dev != device:
                return False
            if current.parent == current:
                return False
            current = current.parent
    except (OSError, ValueError):
        return False
    return True


def _maybe_in_git_work_tree(folder: Path) -> bool:
    """Whether git could have a say: a `.git` folder or file in the folder or above it, or git pointed
    elsewhere by GIT_DIR / GIT_WORK_TREE. Saves starting git for every folder outside a repository."""
    if os.environ.get("GIT_DIR") or os.environ.get("GIT_WORK_TREE"):
        return True
    try:
        start = Path(os.path.abspath(folder))
        return any(os.path.lexists(candidate / ".git") for candidate in (start, *start.parents))
    except (OSError, ValueError):
        return True  # let git decide
