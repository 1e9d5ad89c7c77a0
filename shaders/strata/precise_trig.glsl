// sin, cos, tan, atan and asin good to a few ulp RELATIVE, built from plain arithmetic. GLSL asks nothing
// of the builtins' accuracy; NVIDIA's sin and cos (the MUFU.SIN / MUFU.COS units) are good to about 2^-21.4
// (4e-7) ABSOLUTE over [-pi, pi]: between 1e-7 and 1e-5 an H100's sin and tan were off by up to 100%.
// Mesa's llvmpipe has the same trouble with asin and, milder, atan. Geometry that takes sines of tiny
// angles (relative latitudes, half-differences of coordinates) needs these instead.
// Arguments of sin, cos and tan up to |x| = 25; tests/icosahedral/precise_trig_test.cpp measures them.
#include "strata/constants.glsl"

// pi/2 split as Cody & Waite do (Software Manual for the Elementary Functions, 1980): the first two parts
// have 20 significant bits, so k times them is exact for |k| < 16, and the third is the float nearest the
// rest. Together they hold pi/2 to 2e-21.
const float QUARTER_TURN_1 = 1.570796966552734375;
const float QUARTER_TURN_2 = -6.397576726158149540424346923828125e-7;
const float QUARTER_TURN_3 = -1.6513995574653217e-13;

// x = k pi/2 + r + rLo with |r| <= pi/4 and rLo below half an ulp of r; returns k. x - k C1 is exact (k C1
// is, and the result is on x's grid), and (r1 - r) - k C2 is exactly the rounding error of r (Fast2Sum).
// A fused multiply-add would change none of this, the products being exact; but regrouping into
// x - k (C1 + C2) or simplifying (r1 - r) - k C2 to 0 would, hence precise.
float preciseQuarterTurns(float x, out float r, out float rLo) {
  float k = round(x * (2.0 / PI));
  precise float r1 = x - k * QUARTER_TURN_1;
  precise float hi = r1 - k * QUARTER_TURN_2;
  precise float lo = ((r1 - hi) - k * QUARTER_TURN_2) - k * QUARTER_TURN_3;
  r = hi;
  rLo = lo;
  return k;
}

// sin and cos of r + rLo for |r| <= pi/4: Taylor series, truncated where the next term (r^11 / 11!,
// r^12 / 12!) is below 2^-25 of the result. cos adds 1 - r^2 / 2 in two parts, its rounding error kept.
// precise keeps the small terms summed before the leading one: regrouped, each sum would round twice.
void preciseSinCosKernel(float r, float rLo, out float s, out float c) {
  float r2 = r * r, h = 0.5 * r2;
  float sinTail = r * r2 * (-1.66666667e-1 + r2 * (8.33333333e-3 + r2 * (-1.98412698e-4 + r2 * 2.75573192e-6))) +
                  rLo * (1.0 - h);
  float cosTail = r2 * r2 * (4.16666667e-2 + r2 * (-1.38888889e-3 + r2 * (2.48015873e-5 - r2 * 2.75573192e-7))) -
                  r * rLo;
  precise float w = 1.0 - h;
  precise float wLo = (1.0 - w) - h;  // exact (Sterbenz): 1 - w and h are within a factor of 2
  precise float sinSum = r + sinTail, cosSum = w + (wLo + cosTail);
  s = sinSum;
  c = cosSum;
}

// sin and cos of x, |x| <= 25, to about 1 ulp relative, also at tiny x and next to the zeros.
void preciseSinCos(float x, out float s, out float c) {
  float r, rLo;
  int quadrant = int(preciseQuarterTurns(x, r, rLo)) & 3;
  float sr, cr;
  preciseSinCosKernel(r, rLo, sr, cr);
  float sq = (quadrant & 1) == 0 ? sr : cr, cq = (quadrant & 1) == 0 ? cr : sr;
  s = (quadrant & 2) == 0 ? sq : -sq;
  c = ((quadrant + 1) & 2) == 0 ? cq : -cq;
}

// Instead of sin: NVIDIA's builtin is good to 4e-7 absolute only (see the top).
float preciseSin(float x) {
  float s, c;
  preciseSinCos(x, s, c);
  return s;
}

// Instead of cos: NVIDIA's builtin is good to 4e-7 absolute only, so wrong relatively near pi/2.
float preciseCos(float x) {
  float s, c;
  preciseSinCos(x, s, c);
  return c;
}

// Instead of tan, which NVIDIA builds from its absolute-error sin and cos; relative also near pi/2.
float preciseTan(float x) {
  float s, c;
  preciseSinCos(x, s, c);
  return s / c;
}

// atan(u) for |u| <= 1/2: Taylor series through u^21; the next term, u^23 / 23, is below 2^-25 of atan(u).
float preciseAtanKernel(float u) {
  float u2 = u * u;
  float p = 4.76190476e-2;
  p = -5.26315789e-2 + u2 * p;
  p = 5.88235294e-2 + u2 * p;
  p = -6.66666667e-2 + u2 * p;
  p = 7.69230769e-2 + u2 * p;
  p = -9.09090909e-2 + u2 * p;
  p = 1.11111111e-1 + u2 * p;
  p = -1.42857143e-1 + u2 * p;
  p = 2.0e-1 + u2 * p;
  p = -3.33333333e-1 + u2 * p;
  return u + u * u2 * p;
}

// Instead of atan(y, x), same quadrants (atan(0, 0) = 0, atan(-0, x < 0) = pi): llvmpipe's is good to 2e-5
// relative only at tiny y / x (NVIDIA's is good). The angle from the x axis is n pi/4 + atan(u): n = 0 for
// |y| <= |x| / 2, n = 2 for |x| <= |y| / 2, and n = 1 between, where |y| - |x| is exact (Sterbenz); |u| <=
// 1/2 then. m pi/2 + a adds the quadrant, m times QUARTER_TURN_1 and _2 being exact; precise keeps the
// small parts added first.
float preciseAtan(float y, float x) {
  float ax = abs(x), ay = abs(y);
  float n = ay <= 0.5 * ax ? 0.0 : (ax <= 0.5 * ay ? 2.0 : 1.0);
  float u = n == 0.0 ? (ax > 0.0 ? ay / ax : 0.0) : (n == 2.0 ? -ax / ay : (ay - ax) / (ay + ax));
  float a = x < 0.0 ? -preciseAtanKernel(u) : preciseAtanKernel(u);
  float m = x < 0.0 ? 2.0 - 0.5 * n : 0.5 * n;
  precise float angle = m * QUARTER_TURN_1 + (a + m * QUARTER_TURN_2);
  return y < 0.0 ? -angle : angle;
}

// Instead of asin: llvmpipe's is good to about 1e-7 absolute only, off by half between 1e-7 and 1e-5
// (NVIDIA's is good). atan(x, sqrt(1 - x^2)), the root's argument taken as (1 - |x|)(1 + |x|) near |x| = 1,
// where 1 - |x| is exact and 1 - x^2 would cancel.
float preciseAsin(float x) {
  float ax = abs(x);
  return preciseAtan(x, sqrt(ax < 0.5 ? 1.0 - x * x : (1.0 - ax) * (1.0 + ax)));
}
