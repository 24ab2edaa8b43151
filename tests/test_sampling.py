"""course.sampling: folding, the box response and the spectrum, against their definitions."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from course.sampling import alias_frequency, box_response, cosine_samples, spectrum

frequencies = st.integers(0, 400).map(lambda n: n / 64)
rates = st.sampled_from([1.0, 2.0, 3.5, 8.0])


@given(frequency=frequencies, rate=rates, phase=st.sampled_from([0.0, 0.3, 1.7]))
def test_a_frequency_and_its_alias_give_the_same_samples(frequency, rate, phase):
    alias = alias_frequency(frequency, rate)
    assert 0.0 <= alias <= rate / 2 + 1e-12
    high = cosine_samples(frequency, rate, 40, phase)
    low = cosine_samples(alias, rate, 40, phase)
    folded = cosine_samples(alias, rate, 40, -phase)  # a mirrored alias also flips the phase
    assert np.allclose(high, low, atol=1e-7) or np.allclose(high, folded, atol=1e-7)


@given(frequency=frequencies, width=st.sampled_from([0.5, 1.0, 3.0]), start=st.floats(-3, 3))
def test_the_box_response_is_the_mean_of_a_cosine_over_the_box(frequency, width, start):
    x = start + (np.arange(20000) + 0.5) / 20000 * width  # the midpoint rule, fine enough
    mean = np.cos(2 * np.pi * frequency * x).mean()
    middle = np.cos(2 * np.pi * frequency * (start + width / 2))
    assert mean == pytest.approx(box_response(frequency, width) * middle, abs=1e-6)


def test_the_spectrum_finds_each_cosine_at_its_frequency_and_amplitude():
    samples = 0.5 + 0.8 * cosine_samples(0.125, 1.0, 64) + 0.3 * cosine_samples(0.25, 1.0, 64)
    frequencies, amplitudes = spectrum(samples, 1.0)
    assert frequencies[[0, -1]].tolist() == [0.0, 0.5]
    found = dict(zip(frequencies.tolist(), amplitudes.round(9).tolist(), strict=True))
    assert found[0.0] == 0.5 and found[0.125] == 0.8 and found[0.25] == 0.3
    assert sum(amplitudes > 1e-9) == 3
    # Above the Nyquist frequency the same samples report the folded frequency.
    _, folded = spectrum(cosine_samples(0.875, 1.0, 64), 1.0)
    assert np.argmax(folded) == np.argmax(spectrum(cosine_samples(0.125, 1.0, 64), 1.0)[1])


def test_bad_input_is_refused_by_name():
    with pytest.raises(ValueError, match="rate"):
        alias_frequency(0.3, 0.0)
    with pytest.raises(ValueError, match="frequency"):
        box_response(float("nan"))
    with pytest.raises(ValueError, match=r"samples must be a 1-D array of at least 2 values"):
        spectrum(np.zeros((3, 3)), 1.0)
    with pytest.raises(TypeError, match="frequency"):
        alias_frequency("high", 1.0)
