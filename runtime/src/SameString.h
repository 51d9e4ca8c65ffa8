#ifndef KSE_RUNTIME_SRC_SAME_STRING_H
#define KSE_RUNTIME_SRC_SAME_STRING_H

#include <cstdint>
#include <cstring>
#include <string>

namespace kse::messaging::detail {

/// Whether two short strings (topics, message type names) are equal: inline, eight bytes at a
/// time. Blackboards and the hub look keys up in short vectors on every read and publish, and a
/// call to memcmp per candidate cost more than the comparison.
inline bool SameString(const std::string& a, const std::string& b) noexcept {
  const std::size_t size = a.size();
  if (size != b.size()) return false;
  const char* p = a.data();
  const char* q = b.data();
  std::size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    std::uint64_t x;
    std::uint64_t y;
    std::memcpy(&x, p + i, 8);
    std::memcpy(&y, q + i, 8);
    if (x != y) return false;
  }
  for (; i < size; ++i) {
    if (p[i] != q[i]) return false;
  }
  return true;
}

/// The first eight bytes of a string (zeros after its end) and its length: keys whose tags differ
/// differ, so a lookup compares whole strings only for the candidate that matches.
struct Tag {
  std::uint64_t head = 0;
  std::size_t size = 0;

  explicit Tag(const std::string& text) noexcept : size(text.size()) {
    if (size >= 8) {
      std::memcpy(&head, text.data(), 8);
    } else {
      for (std::size_t i = 0; i < size; ++i) {
        head |= static_cast<std::uint64_t>(static_cast<unsigned char>(text[i])) << (8 * i);
      }
    }
  }
  bool operator==(const Tag& other) const noexcept { return head == other.head && size == other.size; }
};

}  // namespace kse::messaging::detail

#endif
