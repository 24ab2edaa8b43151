"""Sampling in one dimension: why detail finer than the samples comes back as false detail.

Sampling a signal ``rate`` times per unit keeps only what the samples can
tell apart: a cosine of frequency f gives exactly the same samples as one of
frequency ``f - k * rate`` for every whole k, and of ``k * rate - f``. So
every frequency above the **Nyquist frequency** ``rate / 2`` folds back below
it (:func:`alias_frequency`) and is seen as a coarser pattern: aliasing. The
cure is to remove those frequencies *before* sampling: averaging over each
sample's cell is a box filter, whose frequency response (:func:`box_response`)
falls to zero at ``1 / width``. Supersampling (:mod:`course.sampling.resample`)
estimates that average.

References
----------
.. [1] C. E. Shannon, "Communication in the presence of noise", Proceedings
   of the IRE 37(1), 1949 (the sampling theorem).
.. [2] D. P. Mitchell and A. N. Netravali, "Reconstruction filters in
   computer graphics", SIGGRAPH 1988 (aliasing, pre-filtering).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
from course._validate import as_finite_array, as_int, as_positive_float, as_scalar_parameter
from course.i18n import _

__all__ = ["alias_frequency", "box_response", "cosine_samples", "spectrum"]


def alias_frequency(frequency: Any, rate: float) -> np.ndarray | float:
    """The frequency in [0, rate / 2] whose samples equal those of ``frequency``.

    A cosine ``cos(2 pi f x)`` sampled at ``x = k / rate`` is indistinguishable
    from ``cos(2 pi a x)`` with ``a = |f - rate * round(f / rate)|``: the
    spectrum folds at every multiple of the Nyquist frequency ``rate / 2``.

    Examples
    --------
    >>> alias_frequency(0.7, 1.0), alias_frequency(0.3, 1.0), alias_frequency(1.25, 1.0)
    (0.30000000000000004, 0.3, 0.25)
    """
    rate = as_positive_float(rate, "rate")
    values = as_finite_array(frequency, "frequency", limits.MAX_PARAMETER, "values")
    folded = np.abs(values - rate * np.round(values / rate))
    return float(folded) if folded.ndim == 0 else folded


def cosine_samples(frequency: float, rate: float, count: int, phase: float = 0.0) -> np.ndarray:
    """``count`` samples of ``cos(2 pi frequency x + phase)`` at ``x = k / rate``.

    Examples
    --------
    >>> cosine_samples(0.25, 1.0, 5).round(12)
    array([ 1.,  0., -1., -0.,  1.])
    """
    rate = as_positive_float(rate, "rate")
    frequency = as_scalar_parameter(frequency, "frequency")
    phase = as_scalar_parameter(phase, "phase")
    count = as_int(count, "count", minimum=0, maximum=limits.MAX_SAMPLES)
    x = np.arange(count) / rate
    return np.cos(2 * np.pi * frequency * x + phase)


def spectrum(samples: Any, rate: float) -> tuple[np.ndarray, np.ndarray]:
    """The amplitude of each frequency in ``samples`` taken ``rate`` times per unit.

    Returns ``(frequencies, amplitudes)`` for 0 ... rate / 2 (the discrete
    Fourier transform of the samples, one side): a cosine of amplitude 1 at
    a frequency the samples resolve shows as amplitude 1 there.

    Examples
    --------
    >>> frequencies, amplitudes = spectrum(cosine_samples(0.125, 1.0, 64), 1.0)
    >>> float(frequencies[np.argmax(amplitudes)]), round(float(amplitudes.max()), 6)
    (0.125, 1.0)
    """
    rate = as_positive_float(rate, "rate")
    values = as_finite_array(samples, "samples", limits.LARGEST, "values")
    if values.ndim != 1 or len(values) < 2:
        raise ValueError(
            _("samples must be a 1-D array of at least 2 values; got shape {values_shape}").format(
                values_shape=values.shape
            )
        )
    amplitudes = np.abs(np.fft.rfft(values)) * 2 / len(values)
    amplitudes[0] /= 2
    if len(values) % 2 == 0:
        amplitudes[-1] /= 2  # the Nyquist bin has no mirror image to share with
    return np.fft.rfftfreq(len(values), 1 / rate), amplitudes


def box_response(frequency: Any, width: float = 1.0) -> np.ndarray | float:
    """How much of a cosine of ``frequency`` survives averaging over a box ``width`` wide.

    The mean of ``cos(2 pi f x)`` over any interval of length w is the cosine
    at the interval's middle times ``sinc(f w) = sin(pi f w) / (pi f w)``:
    1 at f = 0, ``2 / pi`` (0.637) at the Nyquist frequency of a grid of
    spacing w, zero at ``f = 1 / w`` and its multiples, negative (the
    pattern inverted) between them.

    Examples
    --------
    >>> round(box_response(0.5), 4), box_response(1.0), box_response(0.0)
    (0.6366, 0.0, 1.0)
    """
    width = as_positive_float(width, "width")
    values = as_finite_array(frequency, "frequency", limits.MAX_PARAMETER, "values")
    response = np.sinc(values * width)
    response = np.where(np.abs(response) < 1e-15, 0.0, response)
    return float(response) if response.ndim == 0 else response
