// SPDX-License-Identifier: Apache-2.0
// The sRGB transfer function for 8-bit images: PNG output encodes with it,
// PNG textures decode with it.
#pragma once

namespace toroid {

// Linear intensity to an 8-bit sRGB code, rounded to nearest; clamps to
// [0, 255], NaN gives 0. Exactly the rounding of the sRGB formula, by a
// table of the 255 code boundaries (no pow per channel).
unsigned char linear_to_srgb8(double linear);
// The same for n values (an image row: the table is looked up once).
void linear_to_srgb8(const double* linear, int n, unsigned char* codes);

// An 8-bit sRGB code to linear intensity in [0, 1]: the exact
// inverse of linear_to_srgb8, linear_to_srgb8(srgb8_to_linear(c)) == c.
double srgb8_to_linear(unsigned char code);

}  // namespace toroid
