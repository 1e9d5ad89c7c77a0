// Opponent colour spaces, for composite.chroma_fusion ([Kooima 2008, §1.1, §3.4.3], colour-space
// transformations): one channel of lightness or luma (.x), two of chroma (.yz), to and from the composition's
// scene-linear light in Rec. 709 / sRGB primaries with a D65 white (docs/colour.md). `space` numbers them as
// ChromaFusionLayer::Space: 0 CIE L*a*b*, 1 BT.709 Y'CbCr.

// Scene-linear Rec. 709 to CIE XYZ and back (IEC 61966-2-1's matrix, to seven digits, and its inverse),
// columns as GLSL writes them. Its middle row is relative luminance.
const mat3 REC709_TO_XYZ = mat3(0.4124564, 0.2126729, 0.0193339, 0.3575761, 0.7151522, 0.1191920,
                                0.1804375, 0.0721750, 0.9503041);
const mat3 XYZ_TO_REC709 = mat3(3.2404542, -0.9692660, 0.0556434, -1.5371385, 1.8760108, -0.2040259,
                                -0.4985314, 0.0415560, 1.0572252);
const vec3 REC709_LUMINANCE = vec3(0.2126729, 0.7151522, 0.0721750);
// D65, the matrix's row sums, so that every grey has a* = b* = 0.
const vec3 LAB_WHITE = vec3(0.9504700, 1.0, 1.0888300);

// CIE 15:2004's f and its inverse: a cube root above (6/29)^3, a line below.
float labF(float t) { return t > 216.0 / 24389.0 ? pow(t, 1.0 / 3.0) : t * (841.0 / 108.0) + 4.0 / 29.0; }
float labFInverse(float f) { return f > 6.0 / 29.0 ? f * f * f : (f - 4.0 / 29.0) * (108.0 / 841.0); }

vec3 linearToLab(vec3 linear) {
  vec3 xyz = REC709_TO_XYZ * linear / LAB_WHITE;
  vec3 f = vec3(labF(xyz.x), labF(xyz.y), labF(xyz.z));
  return vec3(116.0 * f.y - 16.0, 500.0 * (f.x - f.y), 200.0 * (f.y - f.z));
}

vec3 labToLinear(vec3 lab) {
  float fy = (lab.x + 16.0) / 116.0;
  vec3 f = vec3(fy + lab.y / 500.0, fy, fy - lab.z / 200.0);
  return XYZ_TO_REC709 * (vec3(labFInverse(f.x), labFInverse(f.y), labFInverse(f.z)) * LAB_WHITE);
}

// The sRGB transfer function (IEC 61966-2-1), the encoding 8-bit colour layers were read from: a line below
// 0.0031308, carried on below 0; the power on above 1.
float srgbEncode(float c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }
float srgbDecode(float e) { return e <= 0.04045 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4); }

// Y'CbCr of ITU-R BT.709 (its Kr = 0.2126, Kb = 0.0722, whose primaries are the composition's), applied, as
// the standard and every image file apply it, to gamma-encoded R'G'B': here the sRGB encoding. Unscaled:
// Y' in [0, 1], Cb and Cr in [-0.5, 0.5].
vec3 linearToYCbCr(vec3 linear) {
  vec3 e = vec3(srgbEncode(linear.r), srgbEncode(linear.g), srgbEncode(linear.b));
  float luma = dot(e, vec3(0.2126, 0.7152, 0.0722));
  return vec3(luma, (e.b - luma) / 1.8556, (e.r - luma) / 1.5748);
}

vec3 yCbCrToLinear(vec3 ycc) {
  float r = ycc.x + 1.5748 * ycc.z, b = ycc.x + 1.8556 * ycc.y;
  float g = (ycc.x - 0.2126 * r - 0.0722 * b) / 0.7152;
  return vec3(srgbDecode(r), srgbDecode(g), srgbDecode(b));
}

vec3 toOpponent(vec3 linear, int space) { return space == 0 ? linearToLab(linear) : linearToYCbCr(linear); }
vec3 fromOpponent(vec3 opponent, int space) { return space == 0 ? labToLinear(opponent) : yCbCrToLinear(opponent); }

// The lightness channel of a grey of relative luminance `y`: L*, or the encoded value (a grey's luma).
float opponentLightness(float y, int space) { return space == 0 ? 116.0 * labF(y) - 16.0 : srgbEncode(y); }
