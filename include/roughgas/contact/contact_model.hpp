#pragma once
// Which normal-force law and which end-of-contact criterion the contact integrator uses
// (Brilliantov et al. (1996) eqs. 24-26; docs/model.md §6).
#include <array>
#include <string_view>

namespace roughgas {

// Brilliantov et al. (1996) eq. 24 (xi'' + rho (xi^{3/2} + (3/2) A xi^{1/2} xi') = 0) or
// eq. 25 (xi'' + rho (xi + A xi')^{3/2} = 0).
enum class NormalForm { eq24, eq25 };

// docs/model.md §6: "force" ends the contact when the total normal force first reaches zero (default,
// no attraction); "separation" ends it at xi = 0 (the paper's eq. 26 read literally).
enum class ContactEnd { force, separation };

struct ContactModel {
    NormalForm form = NormalForm::eq24;
    ContactEnd end = ContactEnd::force;
    friend bool operator==(const ContactModel&, const ContactModel&) = default;
};

inline constexpr std::array<std::string_view, 2> normal_form_names{"eq24", "eq25"};
inline constexpr std::array<std::string_view, 2> contact_end_names{"force", "separation"};

constexpr std::string_view name(NormalForm f) { return normal_form_names[static_cast<int>(f)]; }
constexpr std::string_view name(ContactEnd e) { return contact_end_names[static_cast<int>(e)]; }

} // namespace roughgas
