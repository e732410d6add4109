#pragma once
/// @file
/// A bounded table of the results of a pure function of GiNaC expressions.
///
/// Solving one problem asks for the same factoring, normal form or value again and again (the
/// same sums of moments in several answers, each answer's value checked by two routes). A
/// result is computed once for each argument while the argument is in the table. The table is
/// emptied when full, so it stays small; each call site keeps its own, one per thread (GiNaC is
/// not thread-safe; the server solves one request at a time). Only results are kept: a call
/// that throws is not, and throws again the next time.
#include <ginac/ginac.h>

#include <cstddef>
#include <map>
#include <utility>

namespace wobble::sym {

/// Orders pairs of expressions by GiNaC's canonical comparison, first then second.
struct ExPairLess {
  bool operator()(const std::pair<GiNaC::ex, GiNaC::ex>& a,
                  const std::pair<GiNaC::ex, GiNaC::ex>& b) const {
    const int first = a.first.compare(b.first);
    return first != 0 ? first < 0 : a.second.compare(b.second) < 0;
  }
};

template <class Value, class Key = GiNaC::ex, class Less = GiNaC::ex_is_less>
class Memo {
 public:
  /// compute() for key, or its result from an earlier call with an equal key. A copy: compute()
  /// may call get() again (factoring a product factors its factors), and a later call may empty
  /// the table.
  template <class Compute>
  Value get(const Key& key, Compute&& compute) {
    if (const auto it = known_.find(key); it != known_.end()) return it->second;
    Value value = compute();
    if (known_.size() >= kMaxKnown) known_.clear();
    known_.emplace(key, value);
    return value;
  }

 private:
  static constexpr std::size_t kMaxKnown = 1024;
  std::map<Key, Value, Less> known_;
};

}  // namespace wobble::sym
