"""generator/naming.py: word splitting and casing shared by the back ends."""

from generator.naming import camel, snake, upper, words
from generator.targets.cpp import backend as cpp
from generator.targets.python import backend as python
from generator.targets.rust import backend as rust


def test_words_drop_empty_parts():
    assert words("gnss__time_") == ["gnss", "time"]
    assert words("_x") == ["x"] and words("") == []


def test_camel_upper_cases_each_word_and_keeps_the_rest():
    assert camel("llh_position") == "LlhPosition"
    assert camel("GpsTime") == "GpsTime"  # a type name is already CamelCase
    assert camel("ecef_pos_uncertainty_x") == "EcefPosUncertaintyX"
    assert camel("dev_gNSS") == "DevGNSS"


def test_camel_digit_options():
    # C++ and Python join digit words directly; Rust keeps them apart and prefixes a leading digit.
    assert camel("udre_scale_0_5") == "UdreScale05"
    assert camel("udre_scale_0_5", digit_break="_") == "UdreScale0_5"
    assert camel("gx5_45", digit_break="_") == "Gx5_45" and camel("gx5_45") == "Gx545"
    assert camel("a_12", digit_break="_") != camel("a_1_2", digit_break="_")
    assert camel("3dm_cx5") == "3dmCx5"
    assert camel("3dm_cx5", leading_digit="T") == "T3dmCx5"
    assert camel("__", leading_digit="T") == "T" and camel("__") == ""


def test_each_back_end_uses_its_options():
    assert cpp.camel("gx5_45") == python.camel("gx5_45") == "Gx545"
    assert rust.camel("gx5_45") == "Gx5_45" and rust.camel("1pps") == "T1pps"


def test_snake_keeps_acronyms_and_digits():
    assert snake("Gx5BitFlags") == "gx5_bit_flags"
    assert snake("GNSSTime") == "gnss_time"
    assert snake("FilterStatus") == "filter_status"
    assert snake("already_snake") == "already_snake"


def test_upper():
    assert upper("wrong_length") == "WRONG_LENGTH"
