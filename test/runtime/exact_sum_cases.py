#!/usr/bin/env python3
"""Writes the cases of exact_sum_test.cpp: inputs, and their sum computed
exactly with fractions.Fraction and rounded once to double and to float.

Usage: exact_sum_cases.py OUTPUT

Each case is four lines:
  case NAME
  values V V*COUNT ...      (hex floats; V*COUNT is COUNT copies of V)
  double R                  (the expected sum rounded to double, hex)
  float R                   (rounded to float, as the double holding it, hex)
"""
import math
import random
import struct
import sys
from fractions import Fraction

DBL_MAX = sys.float_info.max
TINY = math.ldexp(1.0, -1074)  # smallest subnormal double


def round_to(x, precision, min_exponent, max_exponent):
    """x (a Fraction, not 0) rounded to nearest, ties to even, in a binary
    format with `precision` bits, whose smallest normal is 2^(min_exponent-1)
    and whose values are below 2^max_exponent: a Python float (inf past it)."""
    sign = -1 if x < 0 else 1
    x = abs(x)
    e = x.numerator.bit_length() - x.denominator.bit_length()
    if Fraction(2) ** e > x:  # make 2^e <= x < 2^(e+1)
        e -= 1
    elif Fraction(2) ** (e + 1) <= x:
        e += 1
    quantum = max(e - precision + 1, min_exponent - precision)
    m = round(x / Fraction(2) ** quantum)  # Fraction rounding: half to even
    if m.bit_length() - 1 + quantum >= max_exponent:
        return sign * math.inf
    return sign * math.ldexp(float(m), quantum)


def scaled(v):
    """A finite double as an integer in units of 2^-1074 (exact)."""
    a, b = v.as_integer_ratio()
    return a * (2 ** 1074 // b)


def expected(runs, to_float):
    """The sum of runs [(value, count)] rounded once (docs/semantics.md)."""
    values = [v for v, _ in runs]
    if any(math.isnan(v) for v in values):
        return math.nan
    plus, minus = math.inf in values, -math.inf in values
    if plus and minus:
        return math.nan
    if plus or minus:
        return math.inf if plus else -math.inf
    exact = Fraction(sum(scaled(v) * n for v, n in runs), 2 ** 1074)
    if exact == 0:
        every_negative_zero = values and all(math.copysign(1.0, v) < 0 for v in values)
        return -0.0 if every_negative_zero else 0.0
    if to_float:
        return round_to(exact, 24, -125, 128)
    result = round_to(exact, 53, -1021, 1024)
    if not math.isinf(result):
        assert result == float(exact)  # Python's own correctly rounded division agrees
    return result


def as_float32(v):
    return struct.unpack('f', struct.pack('f', v))[0]


def cases():
    rng = random.Random(20261202)
    p = lambda e: math.ldexp(1.0, e)
    yield 'cancellation', [1e308, 1.0, -1e308]
    yield 'cancellation_1e16', [1e16, 1.0, -1e16]
    yield 'huge_and_tiny', [1e308, 1e-308, -1e308, 1e-308]
    yield 'huge_tiny_subnormal', [1e308, TINY, 1e-308, -1e308, -1e-308]
    yield 'intermediate_overflow', [DBL_MAX, DBL_MAX, -DBL_MAX]
    yield 'overflow', [DBL_MAX, DBL_MAX]
    yield 'overflow_by_rounding', [DBL_MAX, p(970)]  # a tie, to even: 2^1024
    yield 'no_overflow_below_tie', [DBL_MAX, p(969)]
    yield 'negative_overflow', [-DBL_MAX, -p(971)]
    yield 'tie_to_even_down', [1.0, p(-53)]
    yield 'tie_broken_by_sticky', [1.0, p(-53), TINY]
    yield 'tie_to_even_up', [1.0 + p(-52), p(-53)]
    yield 'float_double_rounding', [1.0, p(-24), p(-60)]  # once to float: 1 + 2^-23
    yield 'float_tie', [1.0, p(-24)]
    yield 'float_overflow', [3.4028234663852886e38, p(103)]  # FLT_MAX + half its ulp
    yield 'subnormals', [TINY] * 1000 + [-TINY * 3, p(-1022), -p(-1022)]
    yield 'subnormal_to_normal', [p(-1022) - TINY, TINY]
    yield 'float_subnormals', [p(-149), p(-150), p(-151)]
    yield 'float_underflow_to_minus_zero', [-p(-151), p(-1000)]
    yield 'empty', []
    yield 'negative_zero', [-0.0]
    yield 'negative_zeros', [-0.0] * 5
    yield 'mixed_zeros', [-0.0, 0.0, -0.0]
    yield 'exact_zero', [1.0, -1.0]
    yield 'exact_zero_with_negative_zero', [-0.0, -1.5, 1.5]
    yield 'nan', [1.0, math.nan, 2.0]
    yield 'plus_inf', [1.0, math.inf, -DBL_MAX]
    yield 'minus_inf', [-math.inf, DBL_MAX, DBL_MAX]
    yield 'both_infs', [math.inf, 1.0, -math.inf]
    yield 'equal_tenths', [(0.1, 1000003)]
    yield 'equal_thirds_cancelling', [(1 / 3, 300001), (-1 / 3, 300000)]
    yield 'equal_huge_past_normalisation', [(DBL_MAX, 600000000), (-DBL_MAX, 600000000), 0.5]
    yield 'random_exponents', [rng.choice((-1, 1)) * math.ldexp(rng.random() + 0.5, rng.randint(-1074, 1022))
                               for _ in range(3000)]
    cancelling = [math.ldexp(rng.random(), rng.randint(-60, 60)) for _ in range(2000)]
    cancelling += [-v for v in cancelling] + [math.ldexp(rng.random(), -80) for _ in range(100)]
    yield 'random_cancelling', cancelling
    yield 'random_floats', [as_float32(rng.uniform(-1, 1) * 10 ** rng.randint(-30, 30)) for _ in range(5000)]
    yield 'random_unit', [rng.uniform(-1, 1) for _ in range(100000)]


def main():
    out = []
    for name, values in cases():
        runs = [v if isinstance(v, tuple) else (v, 1) for v in values]  # (value, copies)
        tokens = [v.hex() if n == 1 else f'{v.hex()}*{n}' for v, n in runs]
        out += [f'case {name}', 'values ' + ' '.join(tokens),
                f'double {expected(runs, False).hex()}', f'float {expected(runs, True).hex()}']
    with open(sys.argv[1], 'w') as f:
        f.write('\n'.join(out) + '\n')


if __name__ == '__main__':
    main()
