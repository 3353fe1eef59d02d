"""segments= and no_gravity=: patches of the scene document that the scene reader checks,
named the way Python spells them (docs/architecture.md, "Checked once")."""
import os
import warnings

import pytest

import mmvlab

SOURCE = os.path.abspath(os.environ["MMVLAB_SOURCE_DIR"])


def test_segments_are_checked_by_the_reader_at_the_bound_and_one_past():
    s = mmvlab.load_scene()
    with pytest.raises(mmvlab.UsageError) as e:
        mmvlab.modes(s, segments=1025, modes=1, error_estimate=False)
    assert str(e.value).startswith("segments=1025: links[0].segments must be an integer from 1 to 1024"), str(e.value)
    with pytest.raises(mmvlab.UsageError, match=r"^segments=-1: links\[0\]\.segments"):
        mmvlab.load_scene(segments=-1)
    one = mmvlab.modes(s, segments=1, modes=1, error_estimate=False)  # the lower bound: a model
    assert one.frequencies_hz.shape == (1,)


def test_a_study_s_segments_read_the_scene_again_with_its_patches():
    s = mmvlab.load_scene(set={"links.link1.length": 2.0}, no_gravity=True)
    m = mmvlab.modes(s, segments=4, modes=3, error_estimate=False)
    again = mmvlab.modes(mmvlab.load_scene(set={"links.link1.length": 2.0}, no_gravity=True, segments=4),
                         modes=3, error_estimate=False)
    assert list(m.frequencies_hz) == list(again.frequencies_hz)
    with_gravity = mmvlab.modes(mmvlab.load_scene(set={"links.link1.length": 2.0}, segments=4), modes=3,
                                error_estimate=False)
    assert list(m.frequencies_hz) != list(with_gravity.frequencies_hz)  # no_gravity kept through segments=


def test_fewer_hinges_than_modes_lower_the_modes_with_a_warning():
    s = mmvlab.load_scene(set={"links.link1.modes": 3})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mmvlab.modes(s, segments=2, modes=1, error_estimate=False)
    assert any("keeps 2 of the 3 modes" in str(w.message) for w in caught), [str(w.message) for w in caught]
