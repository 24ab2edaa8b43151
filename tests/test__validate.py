"""course._validate: its errors name the parameter, in English or in Chinese."""

import numpy as np
import pytest

import course
from course import _validate


@pytest.fixture
def in_chinese():
    course.use_language("zh-CN")
    yield
    course.use_language("en")


def test_errors_name_the_parameter_what_was_expected_and_what_was_given():
    with pytest.raises(
        ValueError, match=r"^image values must lie in \[0, 1\]; got values from 255"
    ):
        _validate.as_image(np.full((2, 2), 255.0))
    with pytest.raises(ValueError, match=r"^p must be finite; got nan at index \(1,\)$"):
        _validate.require_finite(np.array([1.0, np.nan]), "p")


def test_a_validation_error_reads_in_chinese_and_keeps_the_parameters_name(in_chinese):
    with pytest.raises(ValueError, match=r"^image 的值必须在 \[0, 1\] 内；实际取值从 255 到 255"):
        _validate.as_image(np.full((2, 2), 255.0))
    with pytest.raises(TypeError, match=r"^n 必须是整数；实际得到 float 1\.5$"):
        _validate.as_int(1.5, "n")
    with pytest.raises(ValueError, match=r"^t 的取值必须在 ±1000 以内；实际有 1e\+30$"):
        _validate.as_parameter([1e30])
    with pytest.raises(ValueError, match=r"^step 最多只能产生 1048576 个采样（1000 条曲线合计）"):
        _validate.require_step_samples(1e-5, curves=1000)
