#pragma once
// A read-only array whose elements live in storage it shares: a vector it took over, or a range of
// a block owned elsewhere (a cache file read into memory, file_snapshot.h) that stays alive as
// long as an array views it. Copies are cheap and see the same elements, which is what lets a
// body's 100+ MB distance field be used where its cache file was read, without a copy per array.

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace garment {

template <typename T>
class SharedArray {
 public:
  SharedArray() = default;
  explicit SharedArray(std::vector<T> values) {
    auto owned = std::make_shared<const std::vector<T>>(std::move(values));
    size_ = owned->size();
    data_ = std::shared_ptr<const T>(owned, owned->data());
  }
  // `count` elements at `first`, inside a block that `owner` keeps alive.
  SharedArray(std::shared_ptr<const void> owner, const T* first, std::size_t count)
      : data_(std::move(owner), first), size_(count) {}

  const T* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const T& operator[](std::size_t index) const { return data_.get()[index]; }
  const T* begin() const { return data_.get(); }
  const T* end() const { return data_.get() + size_; }
  const T& front() const { return *begin(); }
  const T& back() const { return end()[-1]; }

  friend bool operator==(const SharedArray& a, const SharedArray& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }

 private:
  std::shared_ptr<const T> data_;
  std::size_t size_ = 0;
};

}  // namespace garment
