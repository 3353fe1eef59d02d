"""mmvlab from Python: the same studies as the `mmvlab` command, for scripts and notebooks.

    import mmvlab
    s = mmvlab.load_scene("scenes/mmv-table.yaml", set={"links.link2.E": 45e9})
    m = mmvlab.modes(s, segments=32)
    m.frequencies_hz          # numpy array, Hz
    m.json                    # the dict `mmvlab modes --json` prints for the same request

Every result carries the JSON document the command line prints for the same request
(`.json`, made by the same writer) and its text report (`.text`); the typed attributes
(numpy arrays) are read from that document. Errors raise `mmvlab.Error` subclasses with
the CLI's message: `SceneError` (a scene value, with file:line:col), `SceneFileError`,
`UsageError` (an argument, named as here), `NumericalError`, `UnavailableError`,
`InternalError`. Warnings (likely unit slips, clamped modes) are Python warnings
(`mmvlab.SceneWarning`). A long study can be interrupted with Ctrl-C
(KeyboardInterrupt between two of its steps) and reports its steps to `progress`, a
callable taking a list of (stage, done, total, unit) tuples, outermost first.
See docs/python.md.
"""

import csv as _csv
import inspect as _inspect
import io as _io
import json as _json
import textwrap as _textwrap
import warnings as _warnings

import numpy as _np

from . import _mmvlab
from ._mmvlab import __version__  # noqa: F401  (CMakeLists.txt's project VERSION)
from ._mmvlab import (Error, InternalError, NumericalError, OutputError, Scene,  # noqa: F401
                      SceneError, SceneFileError, UnavailableError, UsageError)

__all__ = ["load_scene", "modes", "converge", "compare", "frf", "rom", "simulate", "check", "place_sensors", "sweep",
           "FrfResult", "RomResult", "SimulateResult", "SweepResult", "ConvergeResult", "CompareResult", "Scene", "Error", "SceneError", "SceneFileError",
           "UsageError", "NumericalError", "UnavailableError", "OutputError", "InternalError", "SceneWarning", "RunWarning",
           "ModesResult", "CheckResult", "check_line_fields", "fields", "field_list_names", "PlacementResult", "correlate", "CorrelateResult", "mode_fields", "trade",
           "TradeResult", "sweep_config", "ConfigSweepResult",
           "TransmissibilityResult", "update", "UpdateResult"]


class SceneWarning(UserWarning):
    """A value no lab article has (a likely unit slip), or a request the model adjusted."""


class RunWarning(UserWarning):
    """What a run found worth a look: a time run's (a torque over capacity, a table program
    past its bandwidth, energy drift: the `warnings` of summary.json) or a correlation's
    (model modes that stop below the test band: the `warnings` of correlation.json)."""


# The parameters most studies share, written once: a docstring's line "    @scene" (and
# @segments, @progress) becomes the text below (help() and the stubs' readers see it).
_SHARED_PARAMETERS = {
    "@scene": ("scene : Scene", "From `load_scene`."),
    "@segments": ("segments : int", "Segments per flexible link for this study (0: the scene's own; as `--segments`)."),
    "@progress": ("progress : callable or None",
                  "Called with a list of (stage, done, total, unit) tuples, outermost first, as the\n"
                  "        study advances (None: silent)."),
}


def _documented(f):
    lines = []
    for line in (f.__doc__ or "").split("\n"):
        key = line.strip()
        if key in _SHARED_PARAMETERS:
            name, text = _SHARED_PARAMETERS[key]
            lines += ["    " + name, "        " + text]
        else:
            lines.append(line)
    f.__doc__ = "\n".join(lines)
    return f


def _warn(messages, category=SceneWarning):
    for w in messages:
        _warnings.warn(w, category, stacklevel=3)


def _yaml_value(key, value):
    """A Python value as the text of `--set KEY=VALUE` (YAML)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float, _np.integer, _np.floating)):
        return repr(float(value)) if isinstance(value, (float, _np.floating)) else str(int(value))
    if isinstance(value, str):
        return value
    if isinstance(value, (list, tuple, dict)):
        return _json.dumps(value)  # JSON is YAML's flow style
    raise UsageError(f"set: {key}: a value of type {type(value).__name__} (give a number, a string, a bool or a list)")


def load_scene(path=None, *, set=None, segments=0, no_gravity=False, strict=False):
    """Reads a scene file (or the embedded default MMV scene), checked as `mmvlab` checks it.

    Parameters
    ----------
    path : str, os.PathLike or None
        The scene file (YAML, docs/scene-format.md); None: the embedded MMV article.
    set : dict or None
        Scene keys to values, e.g. ``{"links.link2.E": 45e9}`` (as `--set KEY=VALUE`;
        SI units as in the file: Pa, m, kg), each checked with its position.
    segments : int
        Every flexible link's segments (0: the scene's own), as `--segments`.
    no_gravity : bool
        Gravity set to zero, as `--no-gravity`.
    strict : bool
        A value no lab article has (a likely unit slip) raises SceneError instead of
        warning (`--strict`).

    Returns
    -------
    Scene
        Picklable; `name`, `source`, `kind` ("article" or "hamsas"), `warnings`.
        Raises SceneError (file:line:col), SceneFileError or UsageError.
    """
    sets = []
    for key, value in (set or {}).items():
        if not isinstance(key, str):
            raise UsageError(f"set: keys are scene paths like 'links.link2.E' (got {key!r})")
        sets.append(f"{key}={_yaml_value(key, value)}")
    scene = _mmvlab.load_scene(None if path is None else str(path), sets, int(segments), bool(no_gravity), bool(strict))
    _warn(scene.warnings)
    return scene


class Result:
    """What a study returns: `.json` (the CLI's JSON document), `.text` (its report)."""

    def __init__(self, json_text, text):
        self.json = _json.loads(json_text)
        self.text = text

    def __getitem__(self, key):
        return self.json[key]

    def __repr__(self):
        scene = self.json.get("scene", "?")  # {name, source} or, in some documents, the name alone
        return f"<mmvlab {type(self).__name__} of {scene.get('name', '?') if isinstance(scene, dict) else scene}>"


class ModesResult(Result):
    """The system modes. Arrays: `frequencies_hz`, `modal_masses_kg`, and
    `shapes[mode, point, component]` at `shape_points` with `shape_components` (per unit
    modal coordinate: m or rad per unit q; NaN where a point has no such component, e.g.
    the rotation at a hinge between two pieces, which has two). On HAM-SAS the "points"
    are the moving bodies and the components `tx ty tz rx ry rz` (translation, small
    rotation; world axes)."""

    def __init__(self, json_text, text, csv):
        super().__init__(json_text, text)
        self.csv = csv
        modes = self.json.get("modes", [])
        self.frequencies_hz = _np.array([m["frequency_hz"] for m in modes], dtype=float)
        self.modal_masses_kg = _np.array([m.get("modal_mass_kg", _np.nan) for m in modes], dtype=float)
        self._shapes = None

    def table(self):
        """The per-mode fields as columns (numbers as numpy arrays, NaN where a mode has
        none; text as lists), for `pandas.DataFrame(m.table())`. The article's: the columns
        of modes.csv, every field of `mode_fields()` that applies to this model (spatial
        fields to the spatial model, damping to a damped scene), under the same names. A
        HAM-SAS result's: the columns of its modes.csv, `fields("hamsas_modes")`."""
        modes = self.json.get("modes", [])
        model = self.json.get("model")
        if isinstance(model, dict):  # the article
            kinds = {"always", "spatial" if model.get("kind") == "spatial" else None,
                     "damped" if self.json.get("damping", {}).get("model", "none") != "none" else None}
            keys = [f["key"] for f in mode_fields() if f["csv"] and f["applies"] in kinds]
        else:
            return _columns(modes, [f for f in fields("hamsas_modes") if f["csv"]])
        columns = {}
        for key in keys:
            values = [m.get(key) for m in modes]
            if all(v is None or isinstance(v, str) for v in values) and any(isinstance(v, str) for v in values):
                columns[key] = values
            else:
                columns[key] = _np.array([_np.nan if v is None else float(v) for v in values], dtype=float)
        return columns

    def _read_shapes(self):
        """The shapes as arrays, read from the document on first use (a sweep that asks
        only for frequencies does not pay for them)."""
        if self._shapes is None:
            shapes = [m.get("shape") for m in self.json.get("modes", [])]
            if shapes and all(shapes) and "body" in shapes[0][0]:  # HAM-SAS: a body's translation and rotation
                points = [b["body"] for b in shapes[0]]
                array = _np.array([[b["translation"] + b["rotation"] for b in s] for s in shapes], dtype=float)
                self._shapes = (points, ["tx", "ty", "tz", "rx", "ry", "rz"], array)
            elif shapes and all(shapes):
                points = [p["point"] for p in shapes[0]]
                components = {}  # every component some point has, in the JSON's order
                for p in shapes[0]:
                    components.update({k: None for k in p if k != "point"})
                array = _np.array([[[p.get(k, _np.nan) for k in components] for p in s] for s in shapes], dtype=float)
                self._shapes = (points, list(components), array)
            else:
                self._shapes = ([], [], _np.zeros((len(shapes), 0, 0)))
        return self._shapes

    @property
    def shape_points(self):
        return self._read_shapes()[0]

    @property
    def shape_components(self):
        return self._read_shapes()[1]

    @property
    def shapes(self):
        return self._read_shapes()[2]


class CheckResult(Result):
    """The feasibility report: `.lines` (dicts as in check.json), `.overall` (its verdict), `.markdown`."""

    def __init__(self, json_text, text, markdown):
        super().__init__(json_text, text)
        self.markdown = markdown
        self.lines = self.json["lines"]
        self.overall = self.json["overall"]

    def table(self):
        """The requirements as columns, one per field of `check_line_fields()` (the columns
        of check.csv, under the same names): demand, capacity and margin_pct as numpy arrays
        (NaN where a line has none), the text fields as lists. For `pandas.DataFrame(c.table())`."""
        return _columns(self.lines, fields("check_lines"))


class PlacementResult(Result):
    """The chosen sensors: `.chosen` (dicts as in placement.json: station, link, x_along_link_m, axis,
    world_x_m, world_y_m, world_z_m, score: the fields of candidates.csv less `chosen`),
    `.target_modes` and `.target_frequencies_hz` (arrays); with `tam=`, `.tams` (placement.json's
    test-analysis models: method, pass, self and cross orthogonality, per-mode checks),
    `tam_table()` (tam.csv's columns, `fields("tam_modes")`) and `.tam_csv`; on a scene with a
    `shaker:`, `.exciter` (placement.json's "exciter": the attachment, per-mode levels, the
    random run, the first ten of the ranking), `exciter_table()` (exciter.csv's columns,
    `fields("exciter_modes")`) and `exciter_ranking_table()` (`fields("exciter_ranking")`)."""

    def __init__(self, json_text, text, tam_csv=""):
        super().__init__(json_text, text)
        self.tam_csv = tam_csv
        self.chosen = self.json["chosen"]
        self.target_modes = _np.array(self.json["target_modes"], dtype=int)
        self.target_frequencies_hz = _np.array(self.json["target_frequencies_hz"], dtype=float)
        self.tams = self.json.get("tam", {}).get("models", [])
        self.exciter = self.json.get("exciter")

    def exciter_table(self):
        """The shaker's per-mode levels as columns (exciter.csv's); empty without a shaker."""
        return _columns(self.exciter["modes"] if self.exciter else [], [f for f in fields("exciter_modes") if f["csv"]])

    def exciter_ranking_table(self):
        """The first ten attachments of the ranking as columns (exciter_ranking.csv's first rows)."""
        return _columns(self.exciter["ranking"] if self.exciter else [], [f for f in fields("exciter_ranking") if f["csv"]])

    def tam_table(self):
        """Every TAM's per-mode checks as columns (tam.csv's, `fields("tam_modes")`: method first)."""
        records = [dict(m, method=t["method"]) for t in self.tams for m in t["modes"]]
        return _columns(records, [f for f in fields("tam_modes") if f["csv"]])


def fields(name):
    """A result's field list, described once in the library (sim/io/fields.hpp).

    Parameters
    ----------
    name : str
        A field list's name (`field_list_names()`: "correlation_pairs", "trade_runs", ...).

    Returns
    -------
    list of dict
        {key, unit, csv (a CSV column), number (numbers, else text), meaning}: the JSON
        records, the CSV columns and the results' `table()` of that kind are all made
        from it.
    """
    return _mmvlab.fields(str(name))


def field_list_names():
    """The names `fields()` takes."""
    return _mmvlab.field_list_names()


def _columns(records, field_list):
    """Records (dicts as in a JSON document) as columns, one per field: numbers as numpy
    arrays (NaN where a record has none), text as lists."""
    columns = {}
    for f in field_list:
        values = [r.get(f["key"]) for r in records]
        if f["number"]:
            columns[f["key"]] = _np.array([_np.nan if v is None else v for v in values], dtype=float)
        else:
            columns[f["key"]] = values
    return columns


def _csv_columns(csv_text, field_list):
    """A CSV table mmvlab wrote, as columns typed by its field list (numbers as numpy
    arrays, NaN for an empty cell; text as lists)."""
    rows = list(_csv.DictReader(_io.StringIO(csv_text)))
    records = [{f["key"]: (None if r[f["key"]] == "" else float(r[f["key"]]) if f["number"] else r[f["key"]])
                for f in field_list if f["csv"]} for r in rows]
    return _columns(records, [f for f in field_list if f["csv"]])


def check_line_fields():
    """The per-requirement fields of `check`, described once in the library
    (sim/io/check_report.hpp): a list of dicts {key, unit ("" for text; "unit": the line's
    own unit; "%"), meaning}; check.json's lines, check.csv and `CheckResult.table()` are
    all made from it."""
    return _mmvlab.check_line_fields()


def mode_fields():
    """The per-mode fields of `modes`, described once in the library (sim/io/mode_fields.hpp):
    a list of dicts {key, unit, csv (a modes.csv column), applies ("always", "spatial",
    "damped"), meaning}; modes.json's mode records, modes.csv and
    `ModesResult.table()` are all made from it."""
    return _mmvlab.mode_fields()


# The verbs whose options are declared once in the library (sim/app/verbs.hpp): each
# function's signature, defaults and docstring are made from `_mmvlab.options(verb)`,
# the list the command line's options and --help are made from too, and its keyword
# arguments are read by that list (an unknown one is a TypeError, a value out of its
# range a UsageError naming it, as the study checks it once for both fronts).
_DECLARED_TYPES = {"bool": "bool", "int": "int", "float": "float", "str": "str", "list[str]": "str or sequence of str",
                   "list[int]": "sequence of int", "list[float]": "sequence of float", "band": "(float, float)",
                   "float?": "float or None", "int?": "int or None", "str?": "str or None"}


def _python_default(option):
    d = option["default"]
    return tuple(d) if isinstance(d, list) else d


def _wrapped(text, indent):
    return _textwrap.fill(text, 88, initial_indent=indent, subsequent_indent=indent, break_on_hyphens=False,
                          break_long_words=False)


def _declared(verb, result, returns, *, segments=True, build=None):
    """The function of a declared verb: `result(json, text, third)` of what the native
    study returns (or `build(native_output)`), its docstring from the declaration and
    `returns`."""
    options = _mmvlab.options(verb)
    summary = dict(_mmvlab.declared_verbs())[verb]
    P = _inspect.Parameter
    params = [P("scene", P.POSITIONAL_OR_KEYWORD)]
    params += [P(o["key"], P.POSITIONAL_OR_KEYWORD) for o in options if o["required"]]
    if segments:
        params.append(P("segments", P.KEYWORD_ONLY, default=0))
    params += [P(o["key"], P.KEYWORD_ONLY, default=_python_default(o)) for o in options if not o["required"]]
    params.append(P("progress", P.KEYWORD_ONLY, default=None))
    signature = _inspect.Signature(params)
    native = getattr(_mmvlab, verb.replace("-", "_"))
    name = verb.replace("-", "_")

    def study(*args, **kwargs):
        given = signature.bind(*args, **kwargs).arguments  # what the caller gave, by name
        scene = given.pop("scene")
        progress = given.pop("progress", None)
        if segments:
            out = native(scene, int(given.pop("segments", 0)), given, progress)
        else:
            out = native(scene, given, progress)
        if build:
            return build(out)
        json_text, text, third, warns = out
        _warn(warns)
        return result(json_text, text, third)

    lines = [f"`mmvlab {verb}`: {summary}.", "", "Parameters", "----------", "@scene"]
    shown = [o for o in options if o["required"]] + ([None] if segments else []) + [o for o in options if not o["required"]]
    for o in shown:
        if o is None:
            lines.append("@segments")
            continue
        lines.append(f"{o['key']} : {_DECLARED_TYPES[o['type']]}")
        lines += _wrapped(f"{o['help']} (`{o['flag']}`)", "    ").split("\n")
    lines += ["@progress", "", "Returns", "-------", result.__name__] + _wrapped(returns, "    ").split("\n")
    study.__name__ = study.__qualname__ = name
    study.__module__ = __name__
    study.__signature__ = signature
    study.__doc__ = "\n".join(("    " + line if line and i > 0 else line) for i, line in enumerate(lines))
    return _documented(study)


modes = _declared("modes", ModesResult,
                  "`frequencies_hz` (Hz), `modal_masses_kg`, `shapes` (m or rad per unit modal coordinate), `.json` "
                  "(modes --json), `.text`, `table()`.")


class FrfResult(Result):
    """Frequency responses: `frequencies_hz` (the grid, with every kept mode's half-power
    band resolved), `H` and `H_reduced` (complex arrays [frequency, output, input] of the
    full and the reduced model, in output units per input unit), `input_names`,
    `output_names`, their units, and `reduced` (the reduced model's state-space matrices
    E, A, B, C, D as numpy arrays: H = C (i w E - A)^-1 B + D)."""

    def __init__(self, d):
        super().__init__(d["json"], d["text"])
        self.frequencies_hz = d["frequencies_hz"]
        self.H = d["H"]
        self.H_reduced = d["H_reduced"]
        self.reduced = d["reduced"]
        self.full = d.get("full")
        self.input_names, self.input_units = self.reduced["input_names"], self.reduced["input_units"]
        self.output_names, self.output_units = self.reduced["output_names"], self.reduced["output_units"]


class RomResult(FrfResult):
    """The reduced-order model (`rom.json` as `.json`): `reduced` and `full` hold E, A, B,
    C, D (what rom.mat and full.mat hold), e.g. for `scipy.signal.StateSpace` after
    `numpy.linalg.solve(E, A)`; the responses as `FrfResult`'s."""


class TransmissibilityResult(Result):
    """frf on a HAM-SAS scene: `frequencies_hz`, `T` (complex array [frequency, table DOF,
    ground DOF]: m/m, m/rad, rad/m or rad/rad), `dof_names` (x, y, z, rx, ry, rz), and with
    `vary`, `varied` (the parameter, its unit and each value's x and z at 10 Hz in dB)."""

    def __init__(self, d):
        super().__init__(d["json"], d["text"])
        self.frequencies_hz = d["frequencies_hz"]
        self.T = d["T"]
        self.dof_names = d["dof_names"]
        self.varied = self.json.get("varied")


def _linear(scene, rom, segments, inputs, outputs, f_min_hz, f_max_hz, points, rom_modes, band_hz, residualize, damping,
            rom_target, target_error, time_budget, progress, vary=None):
    if band_hz is not None and len(band_hz) != 2:
        raise UsageError(f"band_hz: expected (f_min_hz, f_max_hz) (got {band_hz!r})")
    if vary is not None and not isinstance(vary, str):
        key, values = vary  # (key, values) as KEY=V1,V2,...
        vary = f"{key}=" + ",".join(repr(float(v)) for v in values)
    d = _mmvlab.linear(scene, int(segments), [str(x) for x in inputs], [str(x) for x in outputs],
                       None if f_min_hz is None else float(f_min_hz), None if f_max_hz is None else float(f_max_hz),
                       int(points), int(rom_modes), None if band_hz is None else (float(band_hz[0]), float(band_hz[1])),
                       bool(residualize), None if damping is None else float(damping), float(rom_target),
                       float(target_error), float(time_budget), rom, vary or "", progress)
    _warn(d["warnings"])
    if "T" in d:
        return TransmissibilityResult(d)
    return RomResult(d) if rom else FrfResult(d)


@_documented
def frf(scene, *, segments=0, inputs=(), outputs=(), f_min_hz=None, f_max_hz=None, points=400, rom_modes=8, band_hz=None,
        residualize=True, damping=None, rom_target=0.01, target_error=0.0, time_budget=0.0, vary=None, progress=None):
    """`mmvlab frf`: frequency responses of the full and a reduced linear model.

    Parameters
    ----------
    @scene
    @segments
    inputs : sequence of str
        table_x, table_y, torque:JOINT, force:POINT:x|y|z, moment:POINT:rx|ry|rz, shaker
        (empty: the command's defaults).
    outputs : sequence of str
        POINT:AXIS[:disp|vel|acc|acc_abs], strain:A:B[:in|out], stress:STATION[:+y|-y|+z|-z]
        (Pa; empty: the defaults).
    f_min_hz, f_max_hz : float or None
        The grid's lowest and highest frequency, Hz (None: 0.01 and 100).
    points : int
        Log-spaced frequencies, 2 .. 100000.
    rom_modes : int
        Modes kept in the reduced model, 1 .. 10000.
    band_hz : (float, float) or None
        Keep the modes in this band (Hz) instead of `rom_modes`.
    residualize : bool
        Static residualization of the modes left out (False: plain truncation).
    damping : float or None
        Every mode's damping ratio, 0 .. 1 (None: the scene's damping, else 0.01).
    rom_target : float
        The reduced model's relative error that the modes-needed search aims at.
    target_error : float
        Relative error of the responses' discretization (0: off): the fewest segments meeting it.
    time_budget : float
        Wall seconds `target_error` may take (0: no limit).
    vary : str, (str, sequence of float) or None
        HAM-SAS only: one parameter over values, "KEY=V1,V2" or (key, values).
    @progress

    Returns
    -------
    FrfResult, or TransmissibilityResult on a HAM-SAS scene
        `frequencies_hz`, complex `H` and `H_reduced` [frequency, output, input] in
        output units per input unit, the reduced model's E, A, B, C, D.
    """
    return _linear(scene, False, segments, inputs, outputs, f_min_hz, f_max_hz, points, rom_modes, band_hz, residualize,
                   damping, rom_target, target_error, time_budget, progress, vary)


@_documented
def rom(scene, *, segments=0, inputs=(), outputs=(), f_min_hz=None, f_max_hz=None, points=400, rom_modes=8, band_hz=None,
        residualize=True, damping=None, rom_target=0.01, target_error=0.0, time_budget=0.0, progress=None):
    """`mmvlab rom`: the reduced-order state-space model (and the full one) for control design.

    Parameters
    ----------
    @scene
    @segments
    inputs, outputs : sequence of str
        As `frf`'s (empty: the command's defaults).
    f_min_hz, f_max_hz : float or None
        The band the reduced model's error is measured over, Hz (None: 0.01 and 100).
    points : int
        Log-spaced frequencies of that grid, 2 .. 100000.
    rom_modes : int
        Modes kept, 1 .. 10000.
    band_hz : (float, float) or None
        Keep the modes in this band (Hz) instead of `rom_modes`.
    residualize : bool
        Static residualization of the modes left out (every DC gain exact).
    damping : float or None
        Every mode's damping ratio, 0 .. 1 (None: the scene's damping, else 0.01).
    rom_target : float
        The relative error the modes-needed search aims at.
    target_error : float
        Relative discretization error of the responses (0: off).
    time_budget : float
        Wall seconds `target_error` may take (0: no limit).
    @progress

    Returns
    -------
    RomResult
        `reduced` and `full`: E, A, B, C, D (numpy, SI units, with input and output
        names and units), as rom.mat and full.mat hold them.
    """
    return _linear(scene, True, segments, inputs, outputs, f_min_hz, f_max_hz, points, rom_modes, band_hz, residualize,
                   damping, rom_target, target_error, time_budget, progress)


class SimulateResult(Result):
    """A time run: `.json` is summary.json; `history[column]` the sampled quantities
    (numpy arrays, the columns of history.csv with their units in the name, e.g.
    `time_s`, `joint2_torque_n_m`), `columns` their order, `history_array` the whole
    [sample, column] array; `states` and `state_columns` the model's coordinates where
    the run records them (states.csv)."""

    def __init__(self, d):
        super().__init__(d["json"], d["text"])
        self.columns = d["columns"]
        self.history_array = d["history"]
        self.history = {c: self.history_array[:, k] for k, c in enumerate(self.columns)}
        self.state_columns = d["state_columns"]
        self.states = d["states"]

    def torques_table(self):
        """summary.json's torques as columns (`fields("simulate_torques")`): joint,
        peak_torque_n_m, capacity_n_m (NaN: no rating), exceeded."""
        return _columns(self.json.get("torques", []), fields("simulate_torques"))

    def sensors_table(self):
        """summary.json's sensors as columns (`fields("simulate_sensors")`): name, type,
        unit, saturated_samples, samples."""
        return _columns(self.json.get("sensors", []), fields("simulate_sensors"))

    def stress_table(self):
        """summary.json's stress as columns (`fields("simulate_stress")`): each link's
        peak stress over the run (peak_stress_pa, at_s, x_m, face, the loads there), its
        limit (allowable / factor), margin_of_safety, verdict and first_exceeded_s (NaN:
        never); an isolator's run has none (docs/strength.md)."""
        return _columns(self.json.get("stress", []), fields("simulate_stress"))


def _simulate_result(d):
    _warn(d["warnings"])
    result = SimulateResult(d)
    _warn(result.json.get("warnings", []), RunWarning)
    return result


simulate = _declared("simulate", SimulateResult,
                     "`history[column]` (numpy, units in the column names, e.g. `time_s`), `states`, `.json` "
                     "(summary.json).", build=_simulate_result)


def _csv_table(text, number=None):
    """A CSV file's text as (its columns in order, {column: numpy float array, or a list
    of strings for a text column}); an empty cell is NaN. `number[column]`, when given,
    says which columns hold numbers (a field list's word); else a column that reads as
    numbers is one."""
    rows = list(_csv.reader(_io.StringIO(text)))
    columns = rows[0] if rows else []
    table = {}
    for k, c in enumerate(columns):
        cells = [r[k] for r in rows[1:]]
        if number is not None and not number[c]:
            table[c] = cells
            continue
        try:
            table[c] = _np.array([float(x) if x != "" else _np.nan for x in cells], dtype=float)
        except ValueError:
            if number is not None:
                raise
            table[c] = cells
    return columns, table


class ConfigSweepResult(Result):
    """A configuration sweep: `.json` as `sweep-config --json`; `points` its grid points
    (dicts: angles_deg, refined, solved, tracks: each tracked mode's frequency, MAC to the
    previous point, synthesized frequency and error, verdict), `table[column]` and
    `columns` (its sweep.csv: a row per point and track), `csv`."""

    def __init__(self, json_text, text, csv):
        super().__init__(json_text, text)
        self.csv = csv
        self.columns, self.table = _csv_table(csv)
        self.points = self.json["points"]


sweep_config = _declared("sweep-config", ConfigSweepResult, "`points`, `table[column]`, `columns`, `csv`.")


class TradeResult(Result):
    """The speed-accuracy trade: `.json` is trade.json; `runs` its runs (dicts: integrator,
    accuracy, segments, modes, status, tip_error_m, cpu_s, ...), `table[column]` trade.csv's
    columns (`columns` their order, `csv` its text), `target_error_m`, `cheapest` (the
    cheapest run within the target, or None)."""

    def __init__(self, json_text, text, csv):
        super().__init__(json_text, text)
        self.csv = csv
        self.columns, self.table = _csv_table(csv)
        self.runs = self.json["runs"]
        self.target_error_m = self.json["target_error_m"]
        self.cheapest = self.json.get("cheapest_within_target")


trade = _declared("trade", TradeResult, "`runs` (dicts), `cheapest`, `table[column]`, `columns`, `csv`.")


class SweepResult(Result):
    """A design sweep: `.json` is sweep.json; `table[column]` sweep.csv's columns (numpy
    float arrays; text columns such as `status` and `check_overall` as lists), `columns`
    their order, `fields[column]` each one's {key, unit, number, meaning} (sweep.json's
    field list, which also made the CSV), `csv` the file's text and `csv_path` where it is."""

    def __init__(self, json_text, text, table):
        super().__init__(json_text, text)
        self.csv = table
        self.csv_path = self.json["csv"]
        self.fields = {f["key"]: f for f in self.json["fields"]}
        self.columns, self.table = _csv_table(table, {k: f["number"] for k, f in self.fields.items()})


@_documented
def sweep(spec, out, *, jobs=0, shard=None, restart=False, progress=None):
    """`mmvlab sweep SPEC --out OUT`: the design sweep of a spec file (docs/planning.md).

    Parameters
    ----------
    spec : str or os.PathLike
        The sweep spec (YAML).
    out : str or os.PathLike
        The results folder: journal.csv, sweep.csv and sweep.json (a rerun resumes the
        journal). A file there of an output's name that mmvlab did not write is refused
        before anything is computed.
    jobs : int
        Threads, 0 .. 1024 (0: every core).
    shard : (int, int) or None
        (i, n): the i-th of n deterministic slices, into OUT/shard-i-of-n.
    restart : bool
        Start over in a folder that holds another sweep's journal (else refused).
    @progress

    Returns
    -------
    SweepResult
        `table[column]` (numpy; text columns as lists), `fields[column]` ({key, unit,
        number, meaning}), `csv`, `csv_path`.
    """
    if out is None or spec is None:
        raise UsageError(f"{'out' if out is None else 'spec'}: a path is required (got None)")
    if shard is not None and len(shard) != 2:
        raise UsageError(f"shard: expected (i, n) (got {shard!r})")
    json_text, text, table = _mmvlab.sweep(str(spec), str(out), int(jobs),
                                           None if shard is None else (int(shard[0]), int(shard[1])), bool(restart),
                                           progress)
    return SweepResult(json_text, text, table)


class ConvergeResult(Result):
    """Frequencies against segments per link: `.json` as `converge --json`; `segments`
    (the meshes solved), `frequencies_hz[mesh, mode]` (NaN where a mesh has no such mode),
    `richardson_hz` (the extrapolation, NaN where not estimated); `.csv` is converge.csv."""

    def __init__(self, json_text, text, csv):
        super().__init__(json_text, text)
        self.csv = csv
        runs = self.json.get("runs", [])
        modes = self.json.get("modes", [])
        self.segments = _np.array([r.get("segments") for r in runs], dtype=float)
        f = _np.full((len(runs), len(modes)), _np.nan)
        for j, m in enumerate(modes):
            values = m.get("frequency_hz_by_run", [])
            f[:len(values), j] = [_np.nan if v is None else v for v in values]
        self.frequencies_hz = f
        self.richardson_hz = _np.array([_np.nan if m.get("richardson_hz") is None else m["richardson_hz"]
                                        for m in modes], dtype=float)

    def table(self):
        """converge.csv's columns (a row per mode and mesh: the fields of
        `fields("convergence_points")`), for `pandas.DataFrame(c.table())`."""
        return _csv_columns(self.csv, fields("convergence_points"))


class CompareResult(Result):
    """Component modes against system modes: `.json` as `compare --json`, `.markdown` (compare.md)."""

    def __init__(self, json_text, text, markdown):
        super().__init__(json_text, text)
        self.markdown = markdown

    def table(self):
        """The system modes as columns (system_modes.csv's, `fields("compare_system_modes")`),
        for `pandas.DataFrame(c.table())`."""
        return _columns(self.json["system_modes"], [f for f in fields("compare_system_modes") if f["csv"]])

    def synthesis_table(self):
        """The synthesized modes of both methods as columns (synthesis.csv's,
        `fields("compare_synthesis")`: the method first)."""
        records = [dict(row, method=s["method"]) for s in self.json["synthesis"].values() for row in s["modes"]]
        return _columns(records, [f for f in fields("compare_synthesis") if f["csv"]])


converge = _declared("converge", ConvergeResult,
                     "`segments`, `frequencies_hz[mesh, mode]` (Hz), `richardson_hz`, `.csv`.", segments=False)
compare = _declared("compare", CompareResult, "`.json` (compare --json), `.markdown`, `table()`, `synthesis_table()`.")
check = _declared("check", CheckResult,
                  "`.json` (check.json: demand, capacity, margin and verdict per line), `.markdown`, `table()`.")


@_documented
def place_sensors(scene, *, segments=0, modes=(), below_hz=None, spacing=0.1, count=8, triaxial=False, method="efi",
                  tam=(), sensor_mass=0.0, min_separation=0.0, keep_out=(), channels=0, keep_scene_sensors=False,
                  instrument="", iterate_loaded=False, strain_span=0.0, max_deflection=0.0, progress=None):
    """`mmvlab place-sensors`: sensor stations that tell the target modes apart.

    Parameters
    ----------
    @scene
    @segments
    modes : sequence of int
        Target modes, 1-based (empty: every vibration mode below `below_hz`).
    below_hz : float or None
        Target every vibration mode below this frequency, Hz (None: 50).
    spacing : float
        Distance between candidate stations along each link, 0.001 .. 100 m.
    count : int
        Sensors to place (triaxial: blocks), 1 .. 100000.
    triaxial : bool
        Place triaxial blocks instead of uniaxial sensors.
    method : str
        efi (effective independence), mke (modal kinetic energy) or dpr (driving-point residue).
    tam : str or sequence of str
        Test-analysis models to build: "guyan", "irs", "serep" or "all".
    sensor_mass : float
        Each sensor's mass, kg, welded on and the modes solved again.
    min_separation : float
        Least distance between two sensors, m.
    keep_out : str or sequence of str
        "LINK:FROM_M:TO_M" stretches no sensor may go on.
    channels : int
        A channel budget that sets `count` (a triaxial block takes 3; 0: none).
    keep_scene_sensors : bool
        The scene's own accelerometers kept, counted in `count`.
    instrument : str
        The scene's `instruments:` entry placed (its mass, range, resolution).
    iterate_loaded : bool
        Place again on the model carrying the sensors until the set carries itself.
    strain_span : float
        Strain gauges or films this long, m, instead of accelerometers (0: accelerometers).
    max_deflection : float
        The table's dwell levels hold every tip's motion relative to the table within
        this, m, 1e-6 .. 100 (0: no deflection limit; the links' allowables always hold).
    @progress

    Returns
    -------
    PlacementResult
        `.json` (placement.json), `exciter_table()`, `tam_table()`.
    """
    if isinstance(keep_out, str):
        keep_out = [keep_out]
    if isinstance(tam, str):
        tam = [tam]
    json_text, text, tam_csv, warns = _mmvlab.place_sensors(scene, int(segments), [int(m) for m in modes],
                                                            None if below_hz is None else float(below_hz), float(spacing),
                                                            int(count), bool(triaxial), str(method), [str(t) for t in tam],
                                                            float(sensor_mass), float(min_separation),
                                                            [str(k) for k in keep_out], int(channels),
                                                            bool(keep_scene_sensors), str(instrument),
                                                            bool(iterate_loaded), float(strain_span),
                                                            float(max_deflection), progress)
    _warn(warns)
    return PlacementResult(json_text, text, tam_csv)


class CorrelateResult(Result):
    """A measured test against the model (as correlation.json): `.mac` (array [test mode,
    model mode], NaN where a shape is zero at the paired points), `.test_frequencies_hz`,
    `.model_frequencies_hz`, `.pairs` (dicts: test, model, test_hz, model_hz,
    frequency_error, mac, test_damping_ratio, model_damping_ratio; `.table()` as columns), `.frequency_errors` (array, one per pair: f_model / f_test - 1),
    `.frac` (array, one per measured function the model has: its FRAC), `.mac_csv`."""

    def __init__(self, json_text, text, mac_csv):
        super().__init__(json_text, text)
        self.mac_csv = mac_csv
        self.mac = _np.array([[_np.nan if v is None else v for v in row] for row in self.json["mac"]], dtype=float)
        self.mac = self.mac.reshape(len(self.json["test_modes"]), len(self.json["model_modes"]))
        self.test_frequencies_hz = _np.array([m["frequency_hz"] for m in self.json["test_modes"]], dtype=float)
        self.model_frequencies_hz = _np.array([m["frequency_hz"] for m in self.json["model_modes"]], dtype=float)
        self.pairs = self.json["pairs"]
        self.frequency_errors = _np.array([p["frequency_error"] for p in self.pairs], dtype=float)
        self.frac = _np.array([f["frac"] for f in self.json["frfs"] if "frac" in f], dtype=float)

    def table(self):
        """The pairs as columns, one per field of `fields("correlation_pairs")` (pairs.csv's
        columns, under the same names), for `pandas.DataFrame(c.table())`."""
        return _columns(self.pairs, fields("correlation_pairs"))


@_documented
def correlate(scene, measured, *, segments=0, pairs=(), pair_distance=0.05, modes=20, mac_threshold=0.7,
              max_frequency_error=0.3, damping=None, tam="", progress=None):
    """`mmvlab correlate`: a measured UFF file against the scene's model.

    Parameters
    ----------
    @scene
    measured : str or os.PathLike
        The measured UFF file (datasets 15/2411 nodes, 55 modes, 58 functions, 164 units).
    @segments
    pairs : sequence of str or dict
        "NODE=POINT" strings or {node: point}: nodes paired by name.
    pair_distance : float
        A node farther than this from the article is not paired, 1e-6 .. 100 m.
    modes : int
        Model modes compared, 1 .. 500.
    mac_threshold : float
        A test and a model mode pair only at or above this MAC, 0 .. 1.
    max_frequency_error : float
        A pair's largest relative frequency error (0.3: +-30 %).
    damping : float or None
        Every mode's damping ratio, 0 .. 1 (None: the scene's damping, else 0.01).
    tam : str
        "FILE[:METHOD]": a tam.mat of place_sensors' output for the test orthogonality.
    @progress

    Returns
    -------
    CorrelateResult
        `mac[test, model]`, `pairs`, `frequency_errors`, `frac`, `table()`.
    """
    if isinstance(pairs, dict):
        pairs = [f"{node}={point}" for node, point in pairs.items()]
    json_text, text, mac_csv, warns = _mmvlab.correlate(scene, int(segments), str(measured), [str(p) for p in pairs],
                                                        float(pair_distance), int(modes), float(mac_threshold),
                                                        float(max_frequency_error),
                                                        None if damping is None else float(damping), str(tam),
                                                        progress)
    _warn(warns)
    result = CorrelateResult(json_text, text, mac_csv)
    _warn(result.json.get("warnings", []), RunWarning)
    return result


class UpdateResult(Result):
    """A model update (as update.json): `.parameters` (dicts: key, line, nominal, lower,
    upper, updated, change, standard_error, interval_low, interval_high, at_bound,
    determined; `.table()` as columns), `.updated` (dict key -> updated value),
    `.pairs` (the measured modes before and after; `.pairs_table()`), `.updated_scene`
    (the scene file's text with the updated values, each commented), `.converged`."""

    def __init__(self, json_text, text, updated_scene):
        super().__init__(json_text, text)
        self.updated_scene = updated_scene
        self.parameters = self.json["parameters"]
        self.updated = {p["key"]: p["updated"] for p in self.parameters}
        self.pairs = self.json["pairs"]
        self.converged = self.json["converged"]

    def table(self):
        """The parameters as columns, one per field of `fields("update_parameters")`
        (parameters.csv's columns, under the same names)."""
        return _columns(self.parameters, fields("update_parameters"))

    def pairs_table(self):
        """The measured modes before and after, as pairs.csv's columns (`fields("update_pairs")`)."""
        return _columns(self.pairs, fields("update_pairs"))


@_documented
def update(scene, params, *, measured=None, segments=0, frequency_sigma=0.01, mac_sigma=0.05, mac=True,
           regularization=0.0, max_iterations=30, pairs=(), pair_distance=0.05, modes=20, mac_threshold=0.7,
           max_frequency_error=0.3, progress=None):
    """`mmvlab update`: scene keys fitted to measured modes (docs/updating.md).

    Parameters
    ----------
    @scene
    params : sequence of str or dict
        "KEY" or "KEY:LO:HI" strings, or {key: (lo, hi)} / {key: None}: the numbers of the
        scene file to fit, within bounds (the key's unit, SI).
    measured : str, os.PathLike or None
        An article's measured UFF file; None for HAM-SAS (the slides' measured features).
    @segments
    frequency_sigma : float
        A frequency error's stated uncertainty, relative, 1e-6 .. 1.
    mac_sigma : float
        (1 - MAC)'s stated uncertainty, 1e-6 .. 1.
    mac : bool
        Fit (1 - MAC) too (False: the frequencies only, `--no-mac`).
    regularization : float
        Pull toward the nominal, residuals per 100 % change, 0 .. 1e6.
    max_iterations : int
        Levenberg-Marquardt iterations, 1 .. 1000.
    pairs, pair_distance, modes, mac_threshold, max_frequency_error
        As `correlate`'s.
    @progress

    Returns
    -------
    UpdateResult
        `parameters`, `updated` ({key: value}), `pairs`, `updated_scene` (text), `converged`.
    """
    if isinstance(params, dict):
        params = [k if b is None else f"{k}:{b[0]!r}:{b[1]!r}" for k, b in params.items()]
    if isinstance(pairs, dict):
        pairs = [f"{node}={point}" for node, point in pairs.items()]
    json_text, text, updated_scene, warns = _mmvlab.update(
        scene, int(segments), [str(p) for p in params], "" if measured is None else str(measured), float(frequency_sigma),
        float(mac_sigma), bool(mac), float(regularization), int(max_iterations), [str(p) for p in pairs],
        float(pair_distance), int(modes), float(mac_threshold), float(max_frequency_error), progress)
    _warn(warns)
    return UpdateResult(json_text, text, updated_scene)
