// Exact by escalation: run an algorithm on Int64; when checked arithmetic reports an
// overflow, run it again on Int128, then on BigInt, and say which type served.
//
// The naming rule (one rule for every function of zdg that involves the integer tower):
//   f<I>(...)      computes on the tower type I; throws OverflowError when an intermediate
//                  leaves I (never a wrong answer, never a silent wrap).
//   f_exact(...)   escalates Int64 -> Int128 -> BigInt (the inputs converted with int_cast,
//                  which throws OverflowError when they do not fit: the next type is tried) and
//                  returns Escalated<R>: the value and the type that served.
// No other function escalates. Examples: floor_sum<I> / floor_sum_exact,
// recognize_dss<I> / recognize_dss_exact, lattice_hull_2d<I> / lattice_hull_2d_exact,
// lattice_hull_3d<I> / lattice_hull_3d_exact, maximal_segments<I> / maximal_segments_exact,
// digital_moments<I> / digital_moments_exact, disc_hull<I> / disc_hull_exact.
//
// Writing an _exact function:
//   auto r = zdg::escalate([&]<class I>(std::type_identity<I>) { return f<I>(...); });
//   r.value  the result (its type must not depend on I: convert with to_bigint/to_string)
//   r.served IntKind::int64, int128 or bigint
//
// Cost: a run that overflows is wasted, so an overflowing input costs at most the int64
// and int128 attempts on top of the BigInt run. Inputs that are known to need a wide type
// can start there with escalate_from(IntKind::int128, f).
#pragma once

#include <zdg/arith/error.hpp>
#include <zdg/arith/integer.hpp>

#include <string_view>
#include <type_traits>

namespace zdg {

enum class IntKind { int64, int128, bigint };

constexpr std::string_view to_string(IntKind k) {
  switch (k) {
  case IntKind::int64:
    return "int64";
  case IntKind::int128:
    return "int128";
  case IntKind::bigint:
    return "bigint";
  }
  return "?";
}

template <TowerInt I>
constexpr IntKind int_kind() {
  if constexpr (std::same_as<I, Int64>) {
    return IntKind::int64;
  } else if constexpr (std::same_as<I, Int128>) {
    return IntKind::int128;
  } else {
    return IntKind::bigint;
  }
}

template <class R>
struct Escalated {
  R value;
  IntKind served;
};

/// Runs f on the tower types from `first` upwards until one does not overflow.
template <class F>
auto escalate_from(IntKind first, F&& f) {
  using R = std::invoke_result_t<F&, std::type_identity<Int64>>;
  static_assert(std::is_same_v<R, std::invoke_result_t<F&, std::type_identity<Int128>>> &&
                    std::is_same_v<R, std::invoke_result_t<F&, std::type_identity<BigInt>>>,
                "escalate: the result type must not depend on the integer type");
  if (first == IntKind::int64) {
    try {
      return Escalated<R>{f(std::type_identity<Int64>{}), IntKind::int64};
    } catch (const OverflowError&) {
    }
  }
  if (first != IntKind::bigint) {
    try {
      return Escalated<R>{f(std::type_identity<Int128>{}), IntKind::int128};
    } catch (const OverflowError&) {
    }
  }
  return Escalated<R>{f(std::type_identity<BigInt>{}), IntKind::bigint};
}

/// Runs f on Int64, then Int128, then BigInt, until one does not overflow.
template <class F>
auto escalate(F&& f) {
  return escalate_from(IntKind::int64, std::forward<F>(f));
}

} // namespace zdg
