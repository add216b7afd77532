#pragma once
// A DEM contact composed of sub-models (docs/architecture.md, The DEM layer): the normal law
// (normal_step.hpp) and, given its force, each sub-model of the list `Subs` (a struct with its
// typed State, used_by(law) and step(SubContext, State&, ContactForce&)). The composition's state
// is every sub-model's State; its Layout says which are in a flat array of doubles (LAMMPS's
// per-contact history) and where, summing their sizes: the sub-models' states in list order, then
// the normal law's (NormalState, and CrackStepState for a crack law).

#include <array>
#include <cstddef>
#include <tuple>
#include <utility>

#include "bounce/dem/normal_step.hpp"
#include "bounce/dem/state.hpp"
#include "bounce/dem/step_types.hpp"

namespace bounce::dem {

namespace detail {

template <class F, std::size_t... I>
void each(F&& f, std::index_sequence<I...>) {
  (f(std::integral_constant<std::size_t, I>{}), ...);
}

// A row of the composition: a sub-model, or one of the normal law's states, and which laws use it.
template <class Sub>
struct Row {
  using State = typename Sub::State;
  static bool used_by(const models::DemModel& law) { return Sub::used_by(law); }
};
template <class S>
struct StateRow {
  using State = S;
  static bool used_by(const models::DemModel& law) { return S::used_by(law); }
};

}  // namespace detail

template <class... Subs>
class Composition {
  using Rows = std::tuple<detail::Row<Subs>..., detail::StateRow<NormalState>, detail::StateRow<CrackStepState>>;
  static constexpr std::size_t count = std::tuple_size_v<Rows>;
  template <class F>
  static void each_row(F&& f) {
    detail::each(std::forward<F>(f), std::make_index_sequence<count>{});
  }

 public:
  using States = std::tuple<typename Subs::State..., NormalState, CrackStepState>;

  /// One contact's state: whether it holds, and each sub-model's.
  struct State {
    bool touching = false;
    States states;
    template <class S>
    S& get() {
      return std::get<S>(states);
    }
    template <class S>
    const S& get() const {
      return std::get<S>(states);
    }
  };

  /// Which states a flat array holds (those its laws use), and their places.
  class Layout {
   public:
    /// The states the law uses.
    void add(const models::DemModel& law) {
      size_ = 0;
      each_row([&](auto i) {
        used_[i] = used_[i] || std::tuple_element_t<i, Rows>::used_by(law);
        offset_[i] = size_;
        if (used_[i]) size_ += std::tuple_element_t<i, States>::size;
      });
    }
    /// Doubles per contact.
    int size() const { return size_; }
    /// The most a contact can hold: every state.
    static constexpr int largest = (Subs::State::size + ... + 0) + NormalState::size + CrackStepState::size;
    /// A contact's state from its flat array (the states not in it are default).
    State read(bool touching, const double* flat) const {
      State state;
      state.touching = touching;
      each_row([&](auto i) {
        if (used_[i]) std::get<i>(state.states) = std::tuple_element_t<i, States>::read(flat + offset_[i]);
      });
      return state;
    }
    /// Writes it (the states in the array).
    void write(const State& state, double* flat) const {
      each_row([&](auto i) {
        if (used_[i]) std::get<i>(state.states).write(flat + offset_[i]);
      });
    }
    /// The flat array of a contact seen from the other body.
    void reverse(const double* from, double* to) const {
      each_row([&](auto i) {
        if (used_[i]) std::tuple_element_t<i, States>::read(from + offset_[i]).reversed().write(to + offset_[i]);
      });
    }

   private:
    std::array<int, count> offset_{};
    std::array<bool, count> used_{};
    int size_ = 0;
  };

  /// The contact's step: the normal law's, then each sub-model's given its force. A contact that
  /// ends in the step leaves a default state.
  static ContactForce step(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                           const StepSettings& s, State& state) {
    ContactForce out;
    const NormalStep normal = normal_step(law, g, k, s, state.touching, state.template get<NormalState>(),
                                          state.template get<CrackStepState>(), out);
    if (!normal.holds) {
      state = State{};
      return out;
    }
    const SubContext c{law, g, k, s, normal.force, normal.previous};
    (Subs::step(c, state.template get<typename Subs::State>(), out), ...);
    return out;
  }
};

}  // namespace bounce::dem
