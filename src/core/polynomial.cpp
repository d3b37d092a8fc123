#include "polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace termpool::core {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();
// Absolute floor for step tolerances, so a root at t == 0 still terminates.
constexpr double kTinyTime = std::numeric_limits<double>::min();
// Iteration caps only guard against pathological inputs; normal calls converge in a few steps
// and even pure bisection over [0, 1e2] reaches adjacent doubles in well under 100 halvings.
constexpr int kMaxIterations = 128;

// Error-free product x*y = p + e (Dekker/Veltkamp without FMA, so it stays exact on targets
// where the compiler cannot contract; with hardware FMA we use it directly, because
// contraction would silently break the splitting).
inline void two_product(double x, double y, double& p, double& e) noexcept {
    p = x * y;
#ifdef FP_FAST_FMA
    e = std::fma(x, y, -p);
#else
    constexpr double kSplit = 134217729.0; // 2^27 + 1
    const double xs = kSplit * x;
    const double xh = xs - (xs - x);
    const double xl = x - xh;
    const double ys = kSplit * y;
    const double yh = ys - (ys - y);
    const double yl = y - yh;
    e = ((xh * yh - p) + xh * yl + xl * yh) + xl * yl;
#endif
}

// f, f' and f'' at one time: the root finders below need all three (model steps use the
// curvature), and evaluating them together shares the powers of t.
struct Sample {
    double t;
    double f;
    double g; // f'
    double h; // f''
};

// Coefficients prepared once per call: derivative coefficients are pre-multiplied so each
// sample is three short independent Horner chains, and |c_k| * 4 eps bounds Horner's rounding.
struct Work {
    double f[5];
    double g[4];
    double h[3];
    double noise[5];
    double jerk[2]; // bound on the third derivative: |f'''(t)| <= jerk[0] + jerk[1] t, t >= 0
};

inline Sample sample_at(const Work& w, double t) noexcept {
    const double f = (((w.f[4] * t + w.f[3]) * t + w.f[2]) * t + w.f[1]) * t + w.f[0];
    const double g = ((w.g[3] * t + w.g[2]) * t + w.g[1]) * t + w.g[0];
    const double h = (w.h[2] * t + w.h[1]) * t + w.h[0];
    return {t, f, g, h};
}

// Bound on the rounding error of evaluating f at t >= 0: below it the sign of f carries no
// information, so a point there is as good a root as double arithmetic can deliver.
inline double noise_at(const Work& w, double t) noexcept {
    return (((w.noise[4] * t + w.noise[3]) * t + w.noise[2]) * t + w.noise[1]) * t + w.noise[0];
}

inline double step_tolerance(double t) noexcept {
    return 2.0 * kEps * t + kTinyTime;
}

// Step from s to the nearest root, on the side given by the sign of s.f (forward when f > 0,
// backward otherwise), of the local quadratic model f + g d + h d^2 / 2. Gap functions are
// squared distances, which look like double roots until the objects are close, so plain Newton
// would crawl at rate 1/2; the model is exact for constant-velocity motion and, choosing the
// root by side, also works from just past a minimum where Newton points the wrong way.
// Returns NaN when the model has no root on that side (callers then bisect).
inline double model_step(const Sample& s) noexcept {
    const double disc = s.g * s.g - 2.0 * s.h * s.f;
    if (!(disc >= 0.0))
        return -s.f / s.g;
    // Stable pair of roots: f / q (the smaller one unless q is tiny) and 2 q / h.
    const double q = -0.5 * (s.g + std::copysign(std::sqrt(disc), s.g));
    const double r_small = q != 0.0 ? s.f / q : 0.0;
    const double r_big = s.h != 0.0 ? 2.0 * q / s.h : std::numeric_limits<double>::quiet_NaN();
    if (s.f > 0.0) {
        if (r_small > 0.0)
            return r_big > 0.0 ? std::min(r_small, r_big) : r_small;
        return r_big > 0.0 ? r_big : std::numeric_limits<double>::quiet_NaN();
    }
    if (r_small < 0.0)
        return r_big < 0.0 ? std::max(r_small, r_big) : r_small;
    return r_big < 0.0 ? r_big : std::numeric_limits<double>::quiet_NaN();
}

// Step toward a root from s: Halley's when s is close to a simple root (the model's cubic order
// without its square root), the side-aware model step otherwise.
inline double root_step(const Sample& s) noexcept {
    if (4.0 * std::fabs(s.f * s.h) <= s.g * s.g) {
        return -2.0 * s.f * s.g / (2.0 * s.g * s.g - s.f * s.h);
    }
    return model_step(s);
}

// First descending crossing of f inside [lo.t, hi.t], given lo.f > 0 >= hi.f and that the
// bracket holds exactly one crossing from > 0 to <= 0 (every point with f > 0 lies before it).
// Safeguarded model-step iteration: a step leaving the bracket, or not shrinking fast enough,
// is replaced by bisection, so convergence never depends on the model being good.
double find_root(const Work& w, Sample lo, Sample hi) noexcept {
    if (hi.g < 0.0 && hi.f >= -noise_at(w, hi.t))
        return hi.t;
    double a = lo.t;
    double b = hi.t;
    // Start from hi: callers usually found it inside the dip near the closest approach, where
    // the local model is at its best; lo is the fallback, bisection the last resort.
    double x = hi.t + model_step(hi);
    if (!(x > a && x < b)) {
        x = lo.t + model_step(lo);
        if (!(x > a && x < b))
            x = a + 0.5 * (b - a);
    }
    double step_before_last = b - a;
    double last_step = b - a;
    for (int it = 0; it < kMaxIterations; ++it) {
        const Sample s = sample_at(w, x);
        const double nz = noise_at(w, x);
        if (s.g < 0.0 && std::fabs(s.f) <= nz)
            return x;
        if (s.f > 0.0) {
            a = x;
        } else {
            b = x;
        }
        double step = root_step(s);
        double next = x + step;
        if (!(next > a && next < b) || std::fabs(step) > 0.5 * std::fabs(step_before_last)) {
            next = a + 0.5 * (b - a);
            if (!(next > a && next < b))
                return a; // bracket is down to adjacent doubles
            step = next - x;
        } else {
            // f(next) differs from the quadratic model's value there by at most the Taylor
            // remainder |f'''| |step|^3 / 6. Once both are below the evaluation noise, next is
            // already a root as far as double can tell, and sampling it only to confirm would
            // cost a full evaluation. The step must also be short against next itself: then the
            // noise at x is the noise at next, and the rounding of the step is below it.
            const double jerk = w.jerk[0] + w.jerk[1] * std::max(x, next);
            const double step3 = step * step * std::fabs(step);
            const double model = s.f + step * (s.g + 0.5 * s.h * step);
            if (std::fabs(step) <= 0x1p-10 * next && std::fabs(model) + jerk * step3 / 6.0 <= nz &&
                s.g + s.h * step + 0.5 * jerk * step * step < 0.0) {
                return next;
            }
        }
        if (std::fabs(step) <= step_tolerance(x))
            return s.f > 0.0 ? x : next;
        step_before_last = last_step;
        last_step = step;
        x = next;
    }
    return a;
}

// Where Newton on f' from one end of [lo, hi] lands inside it, else the middle: the first guess
// for the critical point between two samples whose slopes differ in sign.
double critical_point_guess(const Sample& lo, const Sample& hi) noexcept {
    double x = lo.t - lo.g / lo.h;
    if (!(x > lo.t && x < hi.t)) {
        x = hi.t - hi.g / hi.h;
        if (!(x > lo.t && x < hi.t))
            x = lo.t + 0.5 * (hi.t - lo.t);
    }
    return x;
}

// One safeguarded Newton step on f' from x (sampled as s) inside (lo, hi): bisection when the
// Newton step leaves the bracket or does not shrink fast enough. NaN when the bracket cannot
// shrink any further.
double critical_point_step(double x, const Sample& s, double lo, double hi, double& last_step,
                           double& step_before_last) noexcept {
    double step = -s.g / s.h;
    double next = x + step;
    if (!(next > lo && next < hi) || std::fabs(step) > 0.5 * std::fabs(step_before_last)) {
        next = lo + 0.5 * (hi - lo);
        if (!(next > lo && next < hi))
            return std::numeric_limits<double>::quiet_NaN();
        step = next - x;
    }
    if (std::fabs(step) <= step_tolerance(x))
        return std::numeric_limits<double>::quiet_NaN();
    step_before_last = last_step;
    last_step = step;
    return next;
}

// Convex piece, f(lo) > 0 with f' < 0 there, f(hi) > 0 with f' > 0 there: f has one minimum in
// between and we must decide whether it dips to <= 0. Locate the minimum with safeguarded
// Newton on f'; any sample with f <= 0 gives a bracket for the first crossing, and the tangent
// lower bound (f >= f(x) + f'(x)(t - x) on a convex piece) proves "no dip" early.
double convex_minimum(const Work& w, Sample lo, Sample hi) noexcept {
    if (lo.f + lo.g * (hi.t - lo.t) > 0.0 || hi.f - hi.g * (hi.t - lo.t) > 0.0)
        return kInf;
    double x = critical_point_guess(lo, hi);
    double step_before_last = hi.t - lo.t;
    double last_step = hi.t - lo.t;
    for (int it = 0; it < kMaxIterations; ++it) {
        const Sample s = sample_at(w, x);
        if (s.f <= 0.0)
            return find_root(w, lo, s);
        if (s.g < 0.0) {
            lo = s;
            if (s.f + s.g * (hi.t - s.t) > 0.0)
                return kInf;
        } else if (s.g > 0.0) {
            hi = s;
            if (s.f - s.g * (s.t - lo.t) > 0.0)
                return kInf;
        } else {
            return kInf; // exactly at the minimum, and it is positive
        }
        const double next = critical_point_step(x, s, lo.t, hi.t, last_step, step_before_last);
        if (std::isnan(next))
            return kInf;
        x = next;
    }
    // Not settled in kMaxIterations (a very flat minimum close to t = 0 in a long piece): rather
    // than give up with "no contact", bisect on f'. Each step halves the bracket, so this ends
    // once it is down to adjacent doubles, with f > 0 at both: then no double has f <= 0.
    for (;;) {
        const double mid = lo.t + 0.5 * (hi.t - lo.t);
        if (!(mid > lo.t && mid < hi.t))
            return kInf;
        const Sample s = sample_at(w, mid);
        if (s.f <= 0.0)
            return find_root(w, lo, s);
        if (s.g < 0.0)
            lo = s;
        else if (s.g > 0.0)
            hi = s;
        else
            return kInf; // exactly at the minimum, and it is positive
    }
}

// End of a piece, sampled only when a decision needs it: a hit is usually settled from inside
// the piece, and the horizon end then never has to be evaluated.
struct PieceEnd {
    double t;
    bool known = false;
    Sample s{};

    const Sample& get(const Work& w) noexcept {
        if (!known) {
            s = sample_at(w, t);
            known = true;
        }
        return s;
    }
};

// Convex piece from lo (f > 0, f' < 0) to q. Most calls that reach here are hits whose gap is
// nearly quadratic, so walk down from the left: every landing before the minimum with f > 0 is a
// valid new left end (f >= its tangent, so nothing was skipped), and one or two steps usually
// land inside the dip, which brackets the first crossing.
double convex_descent(const Work& w, Sample lo, PieceEnd& q) noexcept {
    for (int it = 0; it < 6; ++it) {
        if (lo.f + lo.g * (q.t - lo.t) > 0.0)
            return kInf; // tangent stays above 0 up to q
        const double disc = lo.g * lo.g - 2.0 * lo.f * lo.h;
        double step;
        if (disc >= 0.0) {
            step = 2.0 * lo.f / (std::sqrt(disc) - lo.g);
        } else {
            // The model sees no root, which for a squared distance often only means its
            // curvature is a little off (decelerating balls). Schroeder's step, Newton on f / f',
            // is exact for a double root, so it lands near the closest approach: inside the dip
            // for a hit, near the minimum for a miss. Either outcome narrows the search.
            const double den = lo.g * lo.g - lo.f * lo.h;
            if (!(den > 0.0))
                break;
            step = -lo.f * lo.g / den;
        }
        const double x = lo.t + step;
        if (!(x > lo.t && x < q.t))
            break;
        const Sample s = sample_at(w, x);
        const double nz = noise_at(w, x);
        if (s.g < 0.0 && std::fabs(s.f) <= nz)
            return x;
        if (s.f <= 0.0)
            return find_root(w, lo, s);
        if (s.g >= 0.0)
            return convex_minimum(w, lo, s);
        if (step <= step_tolerance(x))
            return x;
        lo = s;
    }
    const Sample& e = q.get(w);
    if (e.f <= 0.0)
        return find_root(w, lo, e);
    if (e.g <= 0.0)
        return kInf; // still descending at q but positive there
    return convex_minimum(w, lo, e);
}

// Concave piece with f(p) <= 0 rising to a maximum and then falling (f'(p) > 0 > f'(q)): the
// opening-overlap case. If the maximum stays <= 0 the answer is the maximum itself (f turns
// down while still overlapping); if f gets positive anywhere, the answer is the later descending
// crossing, if any before q.
double concave_maximum(const Work& w, Sample lo, Sample hi) noexcept {
    const Sample q = hi;
    double x = critical_point_guess(lo, hi);
    double step_before_last = hi.t - lo.t;
    double last_step = hi.t - lo.t;
    for (int it = 0; it < kMaxIterations; ++it) {
        const Sample s = sample_at(w, x);
        if (s.f > 0.0)
            return q.f <= 0.0 ? find_root(w, s, q) : kInf;
        if (s.g > 0.0) {
            lo = s;
        } else if (s.g < 0.0) {
            hi = s;
        } else {
            return x;
        }
        const double next = critical_point_step(x, s, lo.t, hi.t, last_step, step_before_last);
        if (std::isnan(next))
            return x;
        x = next;
    }
    return x;
}

// One piece [p, q] on which f'' keeps one sign. Returns the infimum of S restricted to the
// piece, or +infinity to continue with the next piece. Every case is decided from the end values
// and convexity, so only dips and turning points need iteration.
double solve_piece(const Work& w, const Sample& p, PieceEnd& qe, bool convex) noexcept {
    if (convex) {
        if (p.g >= 0.0)
            return kInf; // f' only grows: f never decreases here
        if (p.f <= 0.0)
            return p.t;
        return convex_descent(w, p, qe);
    }
    if (p.g <= 0.0) { // f' only falls: f decreasing throughout
        if (p.f <= 0.0)
            return p.t;
        const Sample& q = qe.get(w);
        return q.f <= 0.0 ? find_root(w, p, q) : kInf;
    }
    const Sample& q = qe.get(w);
    if (q.g >= 0.0)
        return kInf; // increasing throughout
    if (p.f > 0.0) {
        // The maximum is positive too, so the only candidate is the crossing after it, and
        // every point before that crossing has f > 0: [p, q] is a valid bracket as it stands.
        return q.f <= 0.0 ? find_root(w, p, q) : kInf;
    }
    return concave_maximum(w, p, q);
}

// Cauchy bound: every real root of f, and of f' (whose scaled coefficients are no larger
// relative to its leading one), lies below this, so S cannot start later than it.
double root_bound(const std::array<double, 5>& c) noexcept {
    int n = 4;
    while (n > 0 && c[static_cast<std::size_t>(n)] == 0.0)
        --n;
    if (n == 0)
        return 1.0;
    const double lead = std::fabs(c[static_cast<std::size_t>(n)]);
    double m = 0.0;
    for (int k = 0; k < n; ++k)
        m = std::max(m, std::fabs(c[static_cast<std::size_t>(k)]) / lead);
    return 2.0 * (1.0 + m);
}

} // namespace

int solve_quadratic(double a, double b, double c, double roots[2]) noexcept {
    if (a == 0.0) {
        if (b == 0.0)
            return 0;
        roots[0] = -c / b;
        return 1;
    }
    // Rescale by a power of two (exact) only when b*b or a*c could leave the double range.
    const double m = std::max({std::fabs(a), std::fabs(b), std::fabs(c)});
    if (m > 1e150 || m < 1e-150) {
        const int e = std::ilogb(m);
        a = std::scalbn(a, -e);
        b = std::scalbn(b, -e);
        c = std::scalbn(c, -e);
    }
    const double bb = b * b;
    const double ac4 = 4.0 * a * c;
    double disc = bb - ac4;
    if (std::fabs(disc) < 0.125 * bb) {
        // b^2 and 4ac nearly cancel: recompute from exact products so a near-double root is
        // classified by the coefficients, not by the rounding of their products.
        double p1, e1, p2, e2;
        two_product(b, b, p1, e1);
        two_product(4.0 * a, c, p2, e2);
        disc = (p1 - p2) + (e1 - e2);
    }
    if (disc < 0.0)
        return 0;
    if (disc == 0.0) {
        roots[0] = -0.5 * b / a;
        return 1;
    }
    // Never subtract nearly equal quantities: q has the magnitude of the larger root term.
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    const double r1 = q / a;
    const double r2 = c / q;
    roots[0] = std::min(r1, r2);
    roots[1] = std::max(r1, r2);
    return 2;
}

namespace {

// The search proper, for 0 < H and coefficients whose terms |c_k| H^k are far from the
// overflow and underflow limits (squares and cubes of f, f', f'' and t must stay finite).
// `mag` is sum |c_k| H^k, which the caller has already computed.
double contact_time_in_range(const std::array<double, 5>& c, double H, double mag) noexcept {
    const double H2 = H * H;
    const double H3 = H2 * H;
    const double H4 = H2 * H2;

    // Early outs from monomial-wise bounds over [0, H] (t^k <= H^k): cheap and rigorous once the
    // margin covers the rounding of the bound itself. Most pairs in a shot end here.
    // f' >= 0 everywhere: f never decreases, so S is empty (also covers f(0) <= 0).
    const double g_low = c[1] + std::min(0.0, 2.0 * c[2]) * H + std::min(0.0, 3.0 * c[3]) * H2 +
                         std::min(0.0, 4.0 * c[4]) * H3;
    const double g_mag = std::fabs(c[1]) + 2.0 * std::fabs(c[2]) * H + 3.0 * std::fabs(c[3]) * H2 +
                         4.0 * std::fabs(c[4]) * H3;
    if (g_low > 4.0 * kEps * g_mag)
        return kInf;
    // f > 0 everywhere: never touching.
    if (c[0] > 0.0) {
        const double f_low = c[0] + std::min(0.0, c[1]) * H + std::min(0.0, c[2]) * H2 +
                             std::min(0.0, c[3]) * H3 + std::min(0.0, c[4]) * H4;
        if (f_low > 4.0 * kEps * mag)
            return kInf;
    }

    Work w; // every field is assigned below; zero-filling it first costs a memset per call
    for (int k = 0; k < 5; ++k) {
        const auto i = static_cast<std::size_t>(k);
        w.f[k] = c[i];
        w.noise[k] = 4.0 * kEps * std::fabs(c[i]);
    }
    w.g[0] = c[1];
    w.g[1] = 2.0 * c[2];
    w.g[2] = 3.0 * c[3];
    w.g[3] = 4.0 * c[4];
    w.h[0] = 2.0 * c[2];
    w.h[1] = 6.0 * c[3];
    w.h[2] = 12.0 * c[4];
    w.jerk[0] = 6.0 * std::fabs(c[3]);
    w.jerk[1] = 24.0 * std::fabs(c[4]);

    // Inflection points of f split [0, H] into pieces of fixed convexity; within each piece f'
    // is monotone, so f has at most one turning point and the case analysis per piece is exact.
    // The square root is only paid for when f'' changes sign inside (0, H): either its end
    // values differ in sign, or its vertex lies inside with the opposite sign (tested without
    // dividing: A h(vertex) = (4AC - B^2) / 4 for f'' = A t^2 + B t + C).
    double breaks[4];
    int n_breaks = 0;
    breaks[n_breaks++] = 0.0;
    const double hA = w.h[2];
    const double hB = w.h[1];
    const double hC = w.h[0];
    const double h_end = (hA * H + hB) * H + hC;
    const bool ends_differ = (hC < 0.0) != (h_end < 0.0) || hC == 0.0 || h_end == 0.0;
    // With equal end signs, two roots need the vertex inside and on the other side of zero,
    // which happens exactly when A and C agree in sign and the discriminant is positive.
    const bool dip_inside = (hA > 0.0) == (hC > 0.0) && hA * hB < 0.0 &&
                            std::fabs(hB) < 2.0 * std::fabs(hA) * H && 4.0 * hA * hC < hB * hB;
    if (ends_differ || dip_inside) {
        double inflections[2];
        const int n_infl = solve_quadratic(w.h[2], w.h[1], w.h[0], inflections);
        for (int i = 0; i < n_infl; ++i) {
            if (inflections[i] > 0.0 && inflections[i] < H)
                breaks[n_breaks++] = inflections[i];
        }
    }
    breaks[n_breaks++] = H;

    Sample p{0.0, c[0], c[1], w.h[0]};
    for (int i = 1; i < n_breaks; ++i) {
        PieceEnd q{breaks[i]};
        const double mid = 0.5 * (p.t + q.t);
        double curvature = (w.h[2] * mid + w.h[1]) * mid + w.h[0];
        if (curvature == 0.0)
            curvature = q.get(w).g - p.g;
        const double t = solve_piece(w, p, q, curvature >= 0.0);
        if (t != kInf)
            return t;
        if (i + 1 < n_breaks)
            p = q.get(w);
    }
    return kInf;
}

// f of degree <= 2 (a ball against a line, where the rails and capture lines make up about a
// third of all searches): the answer follows from the roots in closed form, with the same
// conventions as the general search.
double quadratic_contact_time(double c0, double c1, double c2, double H) noexcept {
    auto within = [H](double t) { return t >= 0.0 && t <= H ? t : kInf; };
    double roots[2];
    if (c0 > 0.0) {
        if (c2 == 0.0)
            return c1 < 0.0 ? within(-c0 / c1) : kInf;
        const int n = solve_quadratic(c2, c1, c0, roots);
        if (n < 2)
            return kInf; // no crossing, or a graze
        // Convex: f falls through the smaller root. Concave: the roots straddle 0 and f falls
        // through the larger one.
        return within(c2 > 0.0 ? roots[0] : roots[1]);
    }
    // f(0) <= 0 and not decreasing (the decreasing case never gets here): an opening overlap.
    if (!(c2 < 0.0))
        return kInf; // f' = c1 + 2 c2 t never turns negative
    const double peak = -c1 / (2.0 * c2);
    if (c0 + peak * (c1 + c2 * peak) <= 0.0)
        return within(peak); // turns down while still overlapping
    const int n = solve_quadratic(c2, c1, c0, roots);
    return n == 2 ? within(roots[1]) : kInf;
}

} // namespace

double first_contact_time(const Polynomial4& poly, double horizon) noexcept {
    const std::array<double, 5>& c = poly.c;
    if (!(horizon >= 0.0))
        return kInf;
    if (c[0] <= 0.0 && c[1] < 0.0)
        return 0.0;
    if (horizon == 0.0)
        return kInf;
    if (c[3] == 0.0 && c[4] == 0.0)
        return quadratic_contact_time(c[0], c[1], c[2], horizon);
    if (horizon == kInf) {
        horizon = root_bound(c);
        if (!(horizon < kInf))
            return kInf; // leading coefficient negligible beyond double range
    }

    // Typical SI inputs pass straight through; only extreme scales pay for exact power-of-two
    // rescaling of time (to H ~ 1) and of f (to its largest term ~ 1).
    const double H = horizon;
    const double mag = std::fabs(c[0]) + std::fabs(c[1]) * H + std::fabs(c[2]) * (H * H) +
                       std::fabs(c[3]) * (H * H * H) + std::fabs(c[4]) * ((H * H) * (H * H));
    if (mag == 0.0)
        return kInf; // f == 0: f' is never negative
    if (mag >= 1e-60 && mag <= 1e60 && H >= 1e-30 && H <= 1e30) {
        return contact_time_in_range(c, H, mag);
    }
    const int time_exp = std::ilogb(H);
    int top = std::numeric_limits<int>::min();
    for (int k = 0; k < 5; ++k) {
        const double ck = c[static_cast<std::size_t>(k)];
        if (ck != 0.0)
            top = std::max(top, std::ilogb(ck) + k * time_exp);
    }
    std::array<double, 5> scaled{};
    for (int k = 0; k < 5; ++k) {
        scaled[static_cast<std::size_t>(k)] =
            std::scalbn(c[static_cast<std::size_t>(k)], k * time_exp - top);
    }
    const double h = std::scalbn(H, -time_exp);
    double scaled_mag = 0.0;
    for (int k = 4; k >= 0; --k)
        scaled_mag = scaled_mag * h + std::fabs(scaled[static_cast<std::size_t>(k)]);
    const double t = contact_time_in_range(scaled, h, scaled_mag);
    return t == kInf ? kInf : std::scalbn(t, time_exp);
}

} // namespace termpool::core
