#include "forward/shards.hpp"

#include <charconv>

namespace vern {

std::optional<Shard> parse_shard(std::string_view text) {
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  auto whole = [](std::string_view s) -> std::optional<std::uint32_t> {
    std::uint32_t n = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
    return n;
  };
  const auto k = whole(text.substr(0, slash));
  const auto n = whole(text.substr(slash + 1));
  if (!k || !n || *k < 1 || *k > *n) return std::nullopt;
  return Shard{*k, *n};
}

Slice shard_slice(std::uint32_t total, Shard shard) {
  auto edge = [&](std::uint32_t k) {
    return static_cast<std::uint32_t>(std::uint64_t{total} * k / shard.count);
  };
  const std::uint32_t first = edge(shard.index - 1);
  return {first, edge(shard.index) - first};
}

}  // namespace vern
