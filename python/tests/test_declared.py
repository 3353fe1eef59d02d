"""The declared verbs (sim/app/verbs.hpp): one option list per verb in the library, the
command line's options and --help and Python's signature, defaults, docstring and stubs
all made from it. Here the three are held to each other for every declared verb: a
default, a range or a name that differs between them fails.
"""
import ast
import inspect
import os
import subprocess

import pytest

import mmvlab
from mmvlab import _mmvlab

MMVLAB = os.environ["MMVLAB_BINARY"]
SOURCE = os.path.abspath(os.environ["MMVLAB_SOURCE_DIR"])
VERBS = [name for name, _ in _mmvlab.declared_verbs()]

# A declared type as the stubs (__init__.pyi) annotate it.
STUB_TYPES = {"bool": "bool", "int": "int", "float": "float", "str": "str", "list[str]": "Union[str, Sequence[str]]",
              "list[int]": "Sequence[int]", "list[float]": "Sequence[float]", "band": "Tuple[float, float]",
              "float?": "Optional[float]", "int?": "Optional[int]", "str?": "Optional[str]"}


def function(verb):
    return getattr(mmvlab, verb.replace("-", "_"))


def cli_help(verb):
    r = subprocess.run([MMVLAB, verb, "--help"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout


def stub_functions():
    with open(os.path.join(SOURCE, "python", "mmvlab", "__init__.pyi")) as f:
        tree = ast.parse(f.read())
    return {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}


def test_the_declared_verbs_are_the_seven_migrated_so_far():
    assert VERBS == ["modes", "converge", "compare", "sweep-config", "simulate", "trade", "check"]


@pytest.mark.parametrize("verb", VERBS)
def test_signature_defaults_are_the_declarations(verb):
    sig = inspect.signature(function(verb))
    options = _mmvlab.options(verb)
    names = list(sig.parameters)
    assert names[0] == "scene" and names[-1] == "progress"
    for o in options:
        p = sig.parameters[o["key"]]
        if o["required"]:
            assert p.default is inspect.Parameter.empty and p.kind == p.POSITIONAL_OR_KEYWORD, o["key"]
            continue
        assert p.kind == p.KEYWORD_ONLY, o["key"]
        expected = tuple(o["default"]) if isinstance(o["default"], list) else o["default"]
        assert p.default == expected and type(p.default) is type(expected), (o["key"], p.default, expected)
    declared = {o["key"] for o in options} | {"scene", "segments", "progress"}
    assert set(names) <= declared, set(names) - declared  # nothing in the signature the library does not take


@pytest.mark.parametrize("verb", VERBS)
def test_cli_help_and_python_docstring_say_the_same(verb):
    """Each option's help text (its unit, range and default included) in both fronts."""
    help_text, doc = cli_help(verb), " ".join(function(verb).__doc__.split())
    for o in _mmvlab.options(verb):
        assert f"  {o['flag']} " in help_text, (verb, o["flag"])
        if o["type"] != "bool":  # a flag's help shows no default: its absence is the default
            # The option's entry: its line, and the next when CLI11 puts a long name's text there.
            at = help_text.index(f"  {o['flag']} ")
            end = help_text.find("\n  -", at + 1)
            entry = help_text[at:end if end >= 0 else len(help_text)]
            assert o["help"] in entry, (verb, o["help"], entry)
        assert " ".join(o["help"].split()) in doc, (verb, o["key"])
        assert f"`{o['flag']}`" in doc, (verb, o["key"])


@pytest.mark.parametrize("verb", VERBS)
def test_stubs_list_the_declared_parameters(verb):
    stub = stub_functions()[verb.replace("-", "_")]
    sig = inspect.signature(function(verb))
    params = stub.args.args + stub.args.kwonlyargs
    assert [a.arg for a in params] == list(sig.parameters), verb
    types = {o["key"]: o["type"] for o in _mmvlab.options(verb)}
    for a in params:
        if a.arg in types:
            assert ast.unparse(a.annotation) == STUB_TYPES[types[a.arg]], (verb, a.arg)
    assert [a.arg for a in stub.args.kwonlyargs] == [n for n, p in sig.parameters.items() if p.kind == p.KEYWORD_ONLY]


def test_a_value_is_checked_once_by_the_study_at_its_bound_and_one_past():
    s = mmvlab.load_scene()
    with pytest.raises(mmvlab.UsageError, match=r"^max_segments: must be a finite number of at least 1 and at most 1024 \(got 1025\)"):
        mmvlab.converge(s, max_segments=1025)
    with pytest.raises(mmvlab.UsageError, match=r"^modes: must be a finite number of at least 1 and at most 1000 \(got 0\)"):
        mmvlab.converge(s, modes=0)
    with pytest.raises(mmvlab.UsageError, match=r"^band_hz: expected 0 <= F_MIN_HZ < F_MAX_HZ"):
        mmvlab.check(s, band_hz=(5, 5))
    with pytest.raises(mmvlab.UsageError, match=r"^strains link1\.tip: expected A:B"):
        mmvlab.modes(s, segments=2, strains="link1.tip")
    with pytest.raises(mmvlab.UsageError, match=r"^topologies: unknown value 'ring'"):
        mmvlab.compare(s, topologies=["open", "ring"])
    assert mmvlab.converge(s, max_segments=1, modes=1).segments.tolist() == [1.0]  # at the bounds


def test_wrong_kinds_and_unknown_keywords_are_type_errors():
    s = mmvlab.load_scene()
    with pytest.raises(TypeError, match="unexpected keyword argument 'mode'"):
        mmvlab.modes(s, mode=3)
    with pytest.raises(TypeError, match=r"^modes: expected an int \(got float\)"):
        mmvlab.modes(s, modes=3.0)
    with pytest.raises(TypeError, match=r"^margin: expected a number \(got str\)"):
        mmvlab.check(s, margin="20")
    with pytest.raises(TypeError, match=r"^error_estimate: expected a bool \(got int\)"):
        mmvlab.modes(s, error_estimate=1)


def test_an_option_error_from_below_the_study_names_the_python_keyword():
    """A request only the analysis can judge (sim/modes/compare.cpp's OptionError on
    --topology) is named as Python spells it: the keyword, not the flag."""
    with pytest.raises(mmvlab.UsageError, match=r"^topologies closed: .* has no closures"):
        mmvlab.compare(mmvlab.load_scene(), segments=2, topologies="closed")
