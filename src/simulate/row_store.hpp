#pragma once
/// @file
/// A run's sampled rows, held so that memory does not grow with the number of samples: the
/// first kInMemoryValues numbers stay in memory, beyond that every row goes to an anonymous
/// temporary file (std::tmpfile, removed when closed). Rows are read back in order (for_each,
/// the iterator) or one at a time (operator[]). The largest |value| of each column is kept as
/// rows arrive, for the table's digits and the plot.
#include <cstddef>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

namespace wobble {

class RowStore {
 public:
  /// 2^20 numbers, 8 MiB: a run of 40 000 samples of 26 columns stays in memory.
  static constexpr std::size_t kInMemoryValues = std::size_t{1} << 20;
  /// Appended values gathered before each write to the file (512 KiB).
  static constexpr std::size_t kPendingValues = std::size_t{1} << 16;

  RowStore() = default;
  /// @throws std::invalid_argument for a row whose width differs from the first row's;
  ///         std::runtime_error if the temporary file cannot be written.
  void append(const std::vector<double>& row);

  std::size_t size() const { return rows_; }
  bool empty() const { return rows_ == 0; }
  std::size_t cols() const { return cols_; }
  /// Row k (k < size()). @throws std::out_of_range.
  std::vector<double> operator[](std::size_t k) const;
  std::vector<double> back() const { return (*this)[rows_ - 1]; }
  /// The largest |value| of column j over all rows (0 for none).
  double largest(std::size_t j) const { return largest_.at(j); }

  /// Every row in order; reads the temporary file sequentially.
  void for_each(const std::function<void(std::size_t k, const std::vector<double>& row)>& f) const;

  class const_iterator {
   public:
    const_iterator(const RowStore* s, std::size_t k) : s_(s), k_(k) {}
    std::vector<double> operator*() const { return (*s_)[k_]; }
    const_iterator& operator++() {
      ++k_;
      return *this;
    }
    bool operator!=(const const_iterator& o) const { return k_ != o.k_; }

   private:
    const RowStore* s_;
    std::size_t k_;
  };
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, rows_}; }

 private:
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::size_t rows_ = 0, cols_ = 0;
  std::vector<double> memory_;
  std::shared_ptr<std::FILE> spill_;  ///< shared: a copied result reads the same file
  std::vector<double> largest_;
  /// Rows appended since the last write to the file: written in one go (a seek and a write per
  /// row took 10 s for a million rows), before any read.
  mutable std::vector<double> pending_;
  void spill();
  void flush_pending() const;
};

}  // namespace wobble
