#pragma once
// What one integrated contact returns.

namespace roughgas {

// Normal problem in Hertz units: xi = g_N T X, t = T S, T = rho^{-2/5} g_N^{-1/5}; X'(0) = 1.
struct NormalResult {
    double eps_n = 1;           // eps^N = -X'(S_c) (docs/model.md §6), in [0, 1]
    double duration = 0;        // S_c
    double max_compression = 0; // max X
    bool captured = false;      // separation end only: the particles stopped before xi returned to 0
                                // (eps_n = 0 then)
};

// Physical result of one contact, SI units.
struct ContactResult {
    double eps_n = 1;           // normal restitution, (g^N)' = -eps_n g^N
    double eps_t = 1;           // the paper's convention: (g^T)' = eps_t g^T (docs/model.md §2)
    double beta = -1;           // literature convention: beta = -eps_t
    double duration = 0;        // t_c [s]
    double max_compression = 0; // max xi [m]
    int breaks = 0;             // asperity breaks during the contact (docs/model.md §7)
};

} // namespace roughgas
