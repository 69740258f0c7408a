#include "solver/laws/contact_law.hpp"

#include <concepts>
#include <span>
#include <utility>

#include "grammar/tact_behav/law_catalogue.hpp"

namespace lmgc::solver {
namespace {

// A 3D law's functions take the interaction's LawState3D after it when the law keeps or reads one.
template <class Law>
concept PreparesWithState3D = requires(const Law& law, Interaction3D& c, LawState3D& s, const LawStep& step) {
  prepare(law, c, s, step);
};

template <class Law>
concept HasForm3D = PreparesWithState3D<Law> ||
    requires(const Law& law, Interaction3D& c, const LawStep& step) {
  prepare(law, c, step);
};

template <class Law>
concept FinishesWithState3D = requires(const Law& law, Interaction3D& c, LawState3D& s, const LawStep& step) {
  finish(law, c, s, step);
};

template <class Law>
concept UpdatesAtCheckWithState3D = requires(const Law& law, Interaction3D& c, LawState3D& s,
                                             const Eigen::Vector3d& u, const LawStep& step) {
  { update_at_check(law, c, s, u, step) } -> std::same_as<bool>;
};

template <class Law>
concept UpdatesAtCheck3D = UpdatesAtCheckWithState3D<Law> ||
    requires(const Law& law, Interaction3D& c, const Eigen::Vector3d& u, const LawStep& step) {
  { update_at_check(law, c, u, step) } -> std::same_as<bool>;
};

template <class Law>
concept UpdatesAtCheck2D = requires(const Law& law, LocalProblem2D& c, const Eigen::Vector2d& u,
                                    const LawStep& step) {
  { update_at_check(law, c, u, step) } -> std::same_as<bool>;
};

template <class Law>
concept HasForm2D = requires(const Law& law, LocalProblem2D& c, const LawStep& step) {
  prepare(law, c, step);
};

template <class Law>
concept FinishesWithState2D = requires(const Law& law, Interaction2D& c, LawState2D& s, const LawStep& step) {
  finish(law, c, s, step);
};

// Whether LMGC90 writes internal variables for the law (2D or 3D): looked up in the law catalogue once
// per law type, since the detection of every step asks (scene_keeps_law_state_2d/3d).
template <class Law>
const grammar::LawKind* catalogue_kind() {
  static const grammar::LawKind* const kind = grammar::find_law_kind(Law::keyword);
  return kind;
}

// The position of parameter `name` among the catalogue's parameters of a law, or -1.
int catalogue_position(const grammar::LawKind& kind, std::string_view name) {
  for (std::size_t i = 0; i < kind.parameters.size(); ++i) {
    std::string_view listed = kind.parameters[i];
    listed = listed.substr(0, listed.find_last_not_of(' ') + 1);  // catalogue names are padded to 5
    if (listed == name) return static_cast<int>(i);
  }
  return -1;
}

// Each parameter of the law's table from the card's value at its name's catalogue position (0 past
// the values given); false when a name is not the catalogue's for the keyword.
template <class Law>
bool fill(std::span<const double> values, Law& law) {
  const grammar::LawKind* kind = catalogue_kind<Law>();
  if (!kind) return false;
  for (const LawParameter<Law>& parameter : Law::parameters) {
    const int k = catalogue_position(*kind, parameter.name);
    if (k < 0) return false;
    law.*(parameter.member) =
        static_cast<std::size_t>(k) < values.size() ? values[static_cast<std::size_t>(k)] : 0.0;
  }
  return true;
}

// A law states the dimensions it has, and has the operations of each: a law that declares a
// dimension without its `prepare` (or the reverse) does not compile.
template <class Law>
constexpr bool forms_as_declared = Law::in_2d == HasForm2D<Law>&& Law::in_3d == HasForm3D<Law>;

template <std::size_t... I>
bool from_card(std::string_view keyword, std::span<const double> values, ContactLaw& law,
               std::index_sequence<I...>) {
  static_assert((forms_as_declared<std::variant_alternative_t<I, ContactLaw>> && ...),
                "a law's in_2d / in_3d must match the prepare overloads it has");
  const auto try_one = [&]<std::size_t K>() {
    using Law = std::variant_alternative_t<K, ContactLaw>;
    if (Law::keyword != keyword) return false;
    Law typed{};
    if (!fill(values, typed)) return false;
    law = typed;
    return true;
  };
  return (try_one.template operator()<I>() || ...);
}

}  // namespace

std::string_view law_keyword(const ContactLaw& law) {
  return std::visit([](const auto& p) { return std::decay_t<decltype(p)>::keyword; }, law);
}

int law_internal_count(const ContactLaw& law) {
  return std::visit([](const auto& p) { return std::decay_t<decltype(p)>::internals_2d; }, law);
}

bool law_from_card(std::string_view keyword, std::span<const double> values, ContactLaw& law) {
  return from_card(keyword, values, law, std::make_index_sequence<std::variant_size_v<ContactLaw>>{});
}

bool provided_in_2d(const ContactLaw& law) {
  return std::visit([](const auto& p) { return std::decay_t<decltype(p)>::in_2d; }, law);
}

void prepare_law(const ContactLaw& law, LocalProblem2D& c, const LawStep& step) {
  std::visit(
      [&](const auto& p) {
        if constexpr (HasForm2D<std::decay_t<decltype(p)>>)
          prepare(p, c, step);
        else
          c.inactive = true;  // a 3D-only law: build_scene_2d refuses it first
      },
      law);
}

bool keeps_law_state_2d(const ContactLaw& law) {
  // Its own internals (which its prepare, checks and finish read and write), or internals that
  // LMGC90 writes for it and a Vloc_Rloc.INI may hold.
  return std::visit(
      [](const auto& p) {
        using Law = std::decay_t<decltype(p)>;
        const grammar::LawKind* kind = catalogue_kind<Law>();
        return Law::internals_2d > 0 || FinishesWithState2D<Law> || (kind && kind->internals_2d.count > 0);
      },
      law);
}

void finish_law(const ContactLaw& law, Interaction2D& c, LawState2D& state, const LawStep& step) {
  std::visit(
      [&](const auto& p) {
        using Law = std::decay_t<decltype(p)>;
        if constexpr (FinishesWithState2D<Law>)
          finish(p, c, state, step);
        else if constexpr (HasForm2D<Law>)
          finish(p, c, step);
      },
      law);
}

bool provided_in_3d(const ContactLaw& law) {
  return std::visit([](const auto& p) { return std::decay_t<decltype(p)>::in_3d; }, law);
}

bool keeps_law_state_3d(const ContactLaw& law) {
  // A law whose 3D internals LMGC90 writes keeps them from a Vloc_Rloc.INI to the outputs even where
  // no code of ours reads them.
  return std::visit(
      [](const auto& p) {
        using Law = std::decay_t<decltype(p)>;
        const grammar::LawKind* kind = catalogue_kind<Law>();
        return PreparesWithState3D<Law> || FinishesWithState3D<Law> || UpdatesAtCheckWithState3D<Law> ||
               (kind && kind->internals_3d.count > 0);
      },
      law);
}

bool prepare_law(const ContactLaw& law, Interaction3D& c, LawState3D& state, const LawStep& step) {
  c.covfree.setZero();
  c.inactive = false;
  c.correction = 0.0;
  c.correction_needs_contact = false;
  c.form = LocalForm3D::coulomb;
  c.normal_compliance = 0.0;
  // The law state's cohesive_slope and cohesive_shift are not reset: only the cohesive form reads
  // them, and the law that sets that form writes both (iqs_mac_czm.hpp).
  return std::visit(
      [&](const auto& p) {
        using Law = std::decay_t<decltype(p)>;
        if constexpr (PreparesWithState3D<Law>) {
          prepare(p, c, state, step);
          return true;
        } else if constexpr (HasForm3D<Law>) {
          prepare(p, c, step);
          return true;
        } else {
          return false;
        }
      },
      law);
}

bool updates_at_check(const ContactLaw& law) {
  return std::visit(
      [](const auto& p) {
        using Law = std::decay_t<decltype(p)>;
        return UpdatesAtCheck3D<Law> || UpdatesAtCheck2D<Law>;
      },
      law);
}

bool update_law_at_check(const ContactLaw& law, LocalProblem2D& c, const Eigen::Vector2d& u,
                         const LawStep& step) {
  return std::visit(
      [&](const auto& p) {
        if constexpr (UpdatesAtCheck2D<std::decay_t<decltype(p)>>)
          return update_at_check(p, c, u, step);
        else
          return false;
      },
      law);
}

bool update_law_at_check(const ContactLaw& law, Interaction3D& c, LawState3D& state, const Eigen::Vector3d& u,
                         const LawStep& step) {
  return std::visit(
      [&](const auto& p) {
        using Law = std::decay_t<decltype(p)>;
        if constexpr (UpdatesAtCheckWithState3D<Law>)
          return update_at_check(p, c, state, u, step);
        else if constexpr (UpdatesAtCheck3D<Law>)
          return update_at_check(p, c, u, step);
        else
          return false;
      },
      law);
}

void finish_law(const ContactLaw& law, Interaction3D& c, LawState3D& state, const LawStep& step) {
  std::visit(
      [&](const auto& p) {
        if constexpr (FinishesWithState3D<std::decay_t<decltype(p)>>)
          finish(p, c, state, step);
        else
          finish(p, c, step);
      },
      law);
}

}  // namespace lmgc::solver
