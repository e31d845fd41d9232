#include "roughgas/observables/enskog_usf_theory.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <vector>

// Units inside: m = T = sigma = 1, so n = 6 phi/pi and nu = (16/5) n sqrt(pi).
namespace roughgas {
namespace {

constexpr double pi = std::numbers::pi;
const double sqrt_pi = std::sqrt(pi);

// Nodes and weights on the unit sphere: N-point Gauss-Legendre in n_z (N even) times the 2N-point
// midpoint rule in the azimuth (exact for trigonometric polynomials up to degree 2N - 1).
struct SphereRule {
    std::vector<std::array<double, 3>> n;
    std::vector<double> w;
};

SphereRule sphere_rule(std::size_t n_polar) {
    std::vector<double> z(n_polar), wz(n_polar);
    // Newton on the Legendre polynomial P_N from Tricomi's initial guess.
    const std::size_t N = n_polar;
    for (std::size_t i = 0; i < N; ++i) {
        double x = std::cos(pi * (static_cast<double>(i) + 0.75) / (static_cast<double>(N) + 0.5));
        double dp = 0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1, p1 = x;
            for (std::size_t k = 2; k <= N; ++k) {
                const double p2 =
                    ((2 * static_cast<double>(k) - 1) * x * p1 - (static_cast<double>(k) - 1) * p0) /
                    static_cast<double>(k);
                p0 = p1;
                p1 = p2;
            }
            dp = static_cast<double>(N) * (x * p1 - p0) / (x * x - 1);
            const double dx = p1 / dp;
            x -= dx;
            if (std::abs(dx) < 1e-16)
                break;
        }
        z[i] = x;
        wz[i] = 2 / ((1 - x * x) * dp * dp);
    }
    // The integrand is even under n_z -> -n_z and under (n_x, n_y) -> (-n_x, -n_y) (USF's symmetry;
    // b ~ n_x n_y): the nodes with n_z > 0 and azimuth in [0, pi) carry four times their weight. The
    // full grid has 2N azimuths, 2 pi (k + 1/2)/(2N), of which the first N lie in [0, pi).
    SphereRule rule;
    for (std::size_t i = 0; i < N; ++i) {
        if (z[i] <= 0)
            continue;
        const double s = std::sqrt(1 - z[i] * z[i]);
        for (std::size_t k = 0; k < N; ++k) {
            const double ph = pi * (static_cast<double>(k) + 0.5) / static_cast<double>(N);
            rule.n.push_back({s * std::cos(ph), s * std::sin(ph), z[i]});
            rule.w.push_back(4 * wz[i] * pi / static_cast<double>(N));
        }
    }
    return rule;
}

// The integrand is an entire function of n varying on the angular scale 1/A (A = a sigma sqrt(m/T));
// 32 x 64 nodes are converged to ~1e-14 up to A ~ 6, beyond that the node count grows with A.
const SphereRule& base_rule() {
    static const SphereRule rule = sphere_rule(32);
    return rule;
}
std::size_t polar_nodes_for(double A) {
    return A <= 6 ? 32 : 16 * static_cast<std::size_t>(std::ceil(A / 3));
}

// <Theta(h) h^k w^p> over w = (V_i - V_j).n ~ N(0, 2) (m = T = 1), h = -(w + b) = -g.n, in terms of
// beta = b/2: with w = -2u, h = 2(u - beta), the average is 2^(k+p) int_beta^inf (u - beta)^k (-u)^p
// e^(-u^2) du/sqrt(pi), a combination of K_m = int_beta^inf u^m e^(-u^2) du/sqrt(pi).
struct GaussianCut {
    std::array<double, 7> K{};
    double beta = 0;
    explicit GaussianCut(double beta_) : beta(beta_) {
        const double e = std::exp(-beta * beta) / (2 * sqrt_pi);
        K[0] = std::erfc(beta) / 2;
        K[1] = e;
        double bpow = 1; // beta^(m-1)
        for (std::size_t m = 2; m < K.size(); ++m) {
            bpow *= beta;
            K[m] = 0.5 * static_cast<double>(m - 1) * K[m - 2] + bpow * e;
        }
    }
    double moment(int k, int p) const {
        static constexpr std::array<std::array<double, 4>, 4> binom{
            {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}}};
        double sum = 0, minus_beta_pow = 1; // (-beta)^(k-j), from j = k down
        for (int j = k; j >= 0; --j) {
            sum += binom[k][j] * minus_beta_pow * K[static_cast<std::size_t>(j + p)];
            minus_beta_pow *= -beta;
        }
        return std::ldexp((p % 2 ? -1.0 : 1.0) * sum, k + p);
    }
};

// The moments are linear in c: value at c = 0 plus one tensor per basis element of the traceless
// USF tensors, E_xx = diag(1, 0, -1), E_yy = diag(0, 1, -1), E_xy = (xy + yx).
struct LinearMoments {
    UsfTensor production0, collisional0;
    std::array<UsfTensor, 3> production, collisional;
};

struct Basis {
    double xx, yy, zz, xy;
};
constexpr std::array<Basis, 3> basis{{{1, 0, -1, 0}, {0, 1, -1, 0}, {0, 0, 0, 1}}};

void add_nn(UsfTensor& t, double f, const std::array<double, 3>& n) {
    t.xx += f * n[0] * n[0];
    t.yy += f * n[1] * n[1];
    t.zz += f * n[2] * n[2];
    t.xy += f * n[0] * n[1];
}

UsfTensor scaled(UsfTensor t, double f) {
    t.xx *= f;
    t.yy *= f;
    t.zz *= f;
    t.xy *= f;
    return t;
}

LinearMoments linear_moments(double alpha, double phi, double chi, double a_star) {
    // a sigma sqrt(m/T) = a* nu sigma sqrt(m/T) = a* (16/5) n sigma^3 sqrt(pi) = a* (96/5) phi/sqrt(pi).
    const double A = a_star * 96.0 / 5.0 * phi / sqrt_pi;
    const std::size_t polar_nodes = polar_nodes_for(A);
    const SphereRule large = polar_nodes > 32 ? sphere_rule(polar_nodes) : SphereRule{};
    const SphereRule& rule = polar_nodes > 32 ? large : base_rule();
    const double ap = 1 + alpha;
    LinearMoments m;
    for (std::size_t q = 0; q < rule.w.size(); ++q) {
        const std::array<double, 3>& n = rule.n[q];
        const double w = rule.w[q];
        // b = a sigma n_x n_y shifts g.n; beta = b/v0, v0 = 2 sqrt(T/m) (w = v0 x, x of density
        // e^(-x^2)/sqrt(pi)).
        const GaussianCut G(A * n[0] * n[1] / 2);
        // Grad's factor averaged over the centre-of-mass velocity and the relative velocity normal to n:
        // 1 + c_nn (w^2/4 - 1/2); times W_perp it leaves w (I - n n) c n.
        const double A1 = G.moment(2, 1), A3 = G.moment(2, 3) / 4 - A1 / 2;
        const double B0 = G.moment(3, 0), B2 = G.moment(3, 2) / 4 - B0 / 2;
        const double C0 = G.moment(2, 0), C2 = G.moment(2, 2) / 4 - C0 / 2;
        // m[V_i Delta + Delta V_i + Delta Delta], Delta = (1 + alpha)/2 h n, V_i -> W/2 after the
        // centre-of-mass average: coefficient of n n at c = 0 (S), of c_nn n n (T), and of the
        // (I - n n) c n n + transpose term (U).
        const double S = ap / 2 * A1 + ap * ap / 4 * B0;
        const double T = ap / 2 * A3 + ap * ap / 4 * B2;
        const double U = ap / 4 * A1;
        add_nn(m.production0, w * S, n);
        add_nn(m.collisional0, w * ap / 4 * C0, n);
        for (std::size_t e = 0; e < basis.size(); ++e) {
            const Basis& E = basis[e];
            const double cnn =
                E.xx * n[0] * n[0] + E.yy * n[1] * n[1] + E.zz * n[2] * n[2] + 2 * E.xy * n[0] * n[1];
            const double cn[3] = {E.xx * n[0] + E.xy * n[1], E.xy * n[0] + E.yy * n[1], E.zz * n[2]};
            add_nn(m.production[e], w * (T - 2 * U) * cnn, n);
            UsfTensor& P = m.production[e];
            P.xx += w * U * 2 * cn[0] * n[0];
            P.yy += w * U * 2 * cn[1] * n[1];
            P.zz += w * U * 2 * cn[2] * n[2];
            P.xy += w * U * (cn[0] * n[1] + n[0] * cn[1]);
            add_nn(m.collisional[e], w * ap / 4 * C2 * cnn, n);
        }
    }
    // Lambda = chi sigma^2 n^2 (integral), over n T nu; P^c = chi sigma^3 n^2 (integral), over n T.
    const double production_scale = 5 * chi / (16 * sqrt_pi);
    const double collisional_scale = 6 * phi * chi / pi;
    m.production0 = scaled(m.production0, production_scale);
    m.collisional0 = scaled(m.collisional0, collisional_scale);
    for (std::size_t e = 0; e < basis.size(); ++e) {
        m.production[e] = scaled(m.production[e], production_scale);
        m.collisional[e] = scaled(m.collisional[e], collisional_scale);
    }
    return m;
}

UsfTensor combine(const UsfTensor& t0, const std::array<UsfTensor, 3>& t, const std::array<double, 3>& c) {
    UsfTensor r = t0;
    for (std::size_t e = 0; e < 3; ++e) {
        r.xx += c[e] * t[e].xx;
        r.yy += c[e] * t[e].yy;
        r.zz += c[e] * t[e].zz;
        r.xy += c[e] * t[e].xy;
    }
    return r;
}

void check_parameters(double alpha, double phi, double chi) {
    if (!(alpha >= 0 && alpha <= 1))
        throw std::invalid_argument("Enskog USF theory: alpha must be in [0, 1]");
    if (!(phi >= 0 && phi < 1))
        throw std::invalid_argument("Enskog USF theory: phi must be in [0, 1)");
    if (!(chi > 0 && std::isfinite(chi)))
        throw std::invalid_argument("Enskog USF theory: chi must be finite and > 0");
}

// For a given a*, the yy, zz and xy balances fix c (coordinates on the basis above); returns them and
// the xx balance's residual Lambda_xx - 2 a* c_xy, negative below the steady a* (cooling wins) and
// positive above it (viscous heating wins).
struct Closure {
    std::array<double, 3> c{};
    double residual = 0;
    LinearMoments moments;
};

Closure close_at(double alpha, double phi, double chi, double a_star) {
    Closure cl;
    cl.moments = linear_moments(alpha, phi, chi, a_star);
    const LinearMoments& m = cl.moments;
    // Rows: Lambda_yy = 0, Lambda_zz = 0, Lambda_xy - a* (1 + c_yy) = 0.
    double M[3][4];
    for (std::size_t e = 0; e < 3; ++e) {
        M[0][e] = m.production[e].yy;
        M[1][e] = m.production[e].zz;
        M[2][e] = m.production[e].xy;
    }
    M[2][1] -= a_star;
    M[0][3] = -m.production0.yy;
    M[1][3] = -m.production0.zz;
    M[2][3] = a_star - m.production0.xy;
    // Gaussian elimination with partial pivoting.
    for (int col = 0; col < 3; ++col) {
        int piv = col;
        for (int r = col + 1; r < 3; ++r)
            if (std::abs(M[r][col]) > std::abs(M[piv][col]))
                piv = r;
        if (!(std::abs(M[piv][col]) > 0))
            throw std::runtime_error("Enskog USF theory: singular Grad balance");
        for (int k = 0; k < 4; ++k)
            std::swap(M[col][k], M[piv][k]);
        for (int r = col + 1; r < 3; ++r) {
            const double f = M[r][col] / M[col][col];
            for (int k = col; k < 4; ++k)
                M[r][k] -= f * M[col][k];
        }
    }
    for (int r = 2; r >= 0; --r) {
        double s = M[r][3];
        for (int k = r + 1; k < 3; ++k)
            s -= M[r][k] * cl.c[static_cast<std::size_t>(k)];
        cl.c[static_cast<std::size_t>(r)] = s / M[r][r];
    }
    const UsfTensor production = combine(m.production0, m.production, cl.c);
    cl.residual = production.xx - 2 * a_star * cl.c[2];
    return cl;
}

} // namespace

EnskogUsfMoments enskog_usf_collisional_moments(double alpha, double phi, double chi, double a_star,
                                                const UsfTensor& kinetic) {
    check_parameters(alpha, phi, chi);
    if (!(a_star >= 0 && std::isfinite(a_star)))
        throw std::invalid_argument("Enskog USF theory: a* must be finite and >= 0");
    const double trace = kinetic.xx + kinetic.yy + kinetic.zz;
    if (!(std::abs(trace - 3) <= 1e-9))
        throw std::invalid_argument("Enskog USF theory: tr P^k/(nT) must be 3");
    // Traceless c = P^k/(nT) - I on the basis: c_zz = -c_xx - c_yy is implied.
    const std::array<double, 3> c{kinetic.xx - 1, kinetic.yy - 1, kinetic.xy};
    const LinearMoments m = linear_moments(alpha, phi, chi, a_star);
    return {combine(m.production0, m.production, c), combine(m.collisional0, m.collisional, c)};
}

EnskogUsfState enskog_usf_grad(double alpha, double phi, double chi) {
    check_parameters(alpha, phi, chi);
    if (alpha == 1)
        throw std::invalid_argument("Enskog USF theory: elastic spheres have no steady shear state");
    // Bracket the root: the residual is -3 zeta* chi < 0 at a* = 0 and grows like a*^2 eta*.
    double lo = 0, hi = 0.5;
    double r_lo = close_at(alpha, phi, chi, lo).residual, r_hi = close_at(alpha, phi, chi, hi).residual;
    for (int k = 0; r_hi <= 0; ++k) {
        if (k == 60)
            throw std::runtime_error("Enskog USF theory: no steady shear rate found");
        lo = hi;
        r_lo = r_hi;
        hi *= 2;
        r_hi = close_at(alpha, phi, chi, hi).residual;
    }
    // Illinois regula falsi: superlinear, and never leaves the bracket.
    int side = 0;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
        double x = (lo * r_hi - hi * r_lo) / (r_hi - r_lo);
        if (!(x > lo && x < hi))
            x = 0.5 * (lo + hi);
        const double r = close_at(alpha, phi, chi, x).residual;
        if (r == 0) {
            lo = hi = x;
            break;
        }
        if (r < 0) {
            lo = x;
            r_lo = r;
            if (side == -1)
                r_hi /= 2;
            side = -1;
        } else {
            hi = x;
            r_hi = r;
            if (side == 1)
                r_lo /= 2;
            side = 1;
        }
    }
    const double a_star = 0.5 * (lo + hi);
    const Closure cl = close_at(alpha, phi, chi, a_star);

    EnskogUsfState s;
    s.a_star = a_star;
    s.kinetic = {1 + cl.c[0], 1 + cl.c[1], 1 - cl.c[0] - cl.c[1], cl.c[2]};
    s.collisional = combine(cl.moments.collisional0, cl.moments.collisional, cl.c);
    s.total = {s.kinetic.xx + s.collisional.xx, s.kinetic.yy + s.collisional.yy,
               s.kinetic.zz + s.collisional.zz, s.kinetic.xy + s.collisional.xy};
    s.eta_star = -s.total.xy / a_star;
    s.N1 = s.total.xx - s.total.yy;
    s.N2 = s.total.yy - s.total.zz;
    return s;
}

} // namespace roughgas
