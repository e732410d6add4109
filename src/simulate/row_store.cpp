#include "simulate/row_store.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wobble {

void RowStore::spill() {
  std::FILE* f = std::tmpfile();
  if (f == nullptr) {
    throw std::runtime_error("cannot create a temporary file for the samples (is TMPDIR writable?)");
  }
  spill_.reset(f, Closer{});
  if (!memory_.empty() &&
      std::fwrite(memory_.data(), sizeof(double), memory_.size(), f) != memory_.size()) {
    throw std::runtime_error("cannot write the samples to a temporary file (disk full?)");
  }
  memory_.clear();
  memory_.shrink_to_fit();
}

void RowStore::append(const std::vector<double>& row) {
  if (rows_ == 0) {
    cols_ = row.size();
    largest_.assign(cols_, 0.0);
  } else if (row.size() != cols_) {
    throw std::invalid_argument("row store: a row of " + std::to_string(row.size()) +
                                " values among rows of " + std::to_string(cols_));
  }
  for (std::size_t j = 0; j < cols_; ++j) largest_[j] = std::max(largest_[j], std::abs(row[j]));
  if (!spill_ && memory_.size() + row.size() > kInMemoryValues) spill();
  if (spill_) {
    pending_.insert(pending_.end(), row.begin(), row.end());
    if (pending_.size() >= kPendingValues) flush_pending();
  } else {
    memory_.insert(memory_.end(), row.begin(), row.end());
  }
  ++rows_;
}

void RowStore::flush_pending() const {
  if (pending_.empty()) return;
  std::FILE* f = spill_.get();
  if (std::fseek(f, 0, SEEK_END) != 0 ||
      std::fwrite(pending_.data(), sizeof(double), pending_.size(), f) != pending_.size()) {
    throw std::runtime_error("cannot write the samples to a temporary file (disk full?)");
  }
  pending_.clear();
}

std::vector<double> RowStore::operator[](std::size_t k) const {
  if (k >= rows_) throw std::out_of_range("row store: no row " + std::to_string(k));
  std::vector<double> row(cols_);
  if (!spill_) {
    std::copy_n(memory_.begin() + static_cast<std::ptrdiff_t>(k * cols_), cols_, row.begin());
    return row;
  }
  flush_pending();
  std::FILE* f = spill_.get();
  const long offset = static_cast<long>(k * cols_ * sizeof(double));
  if (std::fseek(f, offset, SEEK_SET) != 0 ||
      std::fread(row.data(), sizeof(double), cols_, f) != cols_) {
    throw std::runtime_error("cannot read the samples back from their temporary file");
  }
  return row;
}

void RowStore::for_each(
    const std::function<void(std::size_t k, const std::vector<double>& row)>& f) const {
  if (!spill_) {
    std::vector<double> row(cols_);
    for (std::size_t k = 0; k < rows_; ++k) {
      std::copy_n(memory_.begin() + static_cast<std::ptrdiff_t>(k * cols_), cols_, row.begin());
      f(k, row);
    }
    return;
  }
  // Read in chunks of rows, each positioned afresh: f may read other rows of this store.
  flush_pending();
  std::FILE* file = spill_.get();
  constexpr std::size_t kChunkRows = 4096;
  std::vector<double> chunk, row(cols_);
  for (std::size_t first = 0; first < rows_; first += kChunkRows) {
    const std::size_t n = std::min(kChunkRows, rows_ - first);
    chunk.resize(n * cols_);
    if (std::fseek(file, static_cast<long>(first * cols_ * sizeof(double)), SEEK_SET) != 0 ||
        std::fread(chunk.data(), sizeof(double), chunk.size(), file) != chunk.size()) {
      throw std::runtime_error("cannot read the samples back from their temporary file");
    }
    for (std::size_t i = 0; i < n; ++i) {
      std::copy_n(chunk.begin() + static_cast<std::ptrdiff_t>(i * cols_), cols_, row.begin());
      f(first + i, row);
    }
  }
}

}  // namespace wobble
