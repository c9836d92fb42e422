"""Prints the constants of shapes/elementary.cpp, computed with mpmath at 1,400 bits: the bits of
2/pi that the argument reduction of cos_sin() multiplies by, pi/2 in the four parts of the
reduction of smaller angles, and pi/2, pi and atan(i/8) as
double-double pairs (the double nearest, then the double nearest the rest). The unit test
test_elementary checks the results they give against Boost.Multiprecision over the whole range of
doubles.

    /usr/bin/python3 scripts/elementary_constants.py
"""
import mpmath

mpmath.mp.prec = 1400
WORDS = 19  # 2/pi to 1,216 bits: the largest double's reduction reads 192 bits from bit 969 on


def hex_double(x):
    return float(x).hex().replace('0x1.0000000000000p', '0x1p')


def double_double(x):
    hi = mpmath.mpf(float(x))
    return f'{{{hex_double(hi)}, {hex_double(x - hi)}}}'


def main():
    scaled = int(mpmath.floor(2 / mpmath.pi * mpmath.mpf(2) ** (64 * WORDS)))
    words = [(scaled >> (64 * (WORDS - 1 - k))) & (2**64 - 1) for k in range(WORDS)]
    print('two_over_pi:')
    for k in range(0, WORDS, 3):
        print('    ' + ', '.join(f'0x{w:016x}' for w in words[k:k + 3]) + ',')
    print('half_pi:', double_double(mpmath.pi / 2))
    print('two_over_pi, nearest:', hex_double(2 / mpmath.pi))
    # pi/2 in four parts, the first three truncated to 33 significant bits.
    rest, parts = mpmath.pi / 2, []
    for _ in range(3):
        scale = mpmath.mpf(2) ** (32 - int(mpmath.floor(mpmath.log(rest, 2))))
        parts.append(mpmath.floor(rest * scale) / scale)
        rest -= parts[-1]
    parts.append(mpmath.mpf(float(rest)))
    print('half_pi parts:', ', '.join(hex_double(p) for p in parts))
    print('pi:', double_double(mpmath.pi))
    print('atan(i/8), i = 1..8:')
    for i in range(1, 9):
        print('    ' + double_double(mpmath.atan(mpmath.mpf(i) / 8)) + ',')


if __name__ == '__main__':
    main()
