// Names to their ids, found by hash.
//
// A grammar may define 200 000 constants or name as many primitives;
// finding each by reading every name defined before it made reading such
// a grammar quadratic (95 s for 200 000 constants). This finds one in
// constant time, with a std::string_view, without building a string.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

namespace vern {

template <class Id>
class NameIndex {
 public:
  std::optional<Id> find(std::string_view name) const {
    const auto it = ids_.find(name);
    if (it == ids_.end()) return std::nullopt;
    return it->second;
  }

  // name -> id, unless the name has an id already (which it keeps).
  void add(std::string_view name, Id id) { ids_.try_emplace(std::string(name), id); }
  void clear() { ids_.clear(); }

 private:
  struct Hash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  std::unordered_map<std::string, Id, Hash, std::equal_to<>> ids_;
};

}  // namespace vern
