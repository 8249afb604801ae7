// Lists of names written "a, b, c": the parameter table's choices and integrators, a section's
// valid keys in messages. One spelling of the separator for every list ClothLab prints or reads.
#pragma once

#include <string>
#include <string_view>

namespace clothlab {

// Appends `name` to `list` ("a, b" + "c" -> "a, b, c").
inline void add_to_list(std::string& list, std::string_view name) {
  if (!list.empty()) list += ", ";
  list += name;
}

// name(item) of every item, as one list.
template <class Items, class Name>
std::string comma_list(const Items& items, Name name) {
  std::string list;
  for (const auto& item : items) add_to_list(list, name(item));
  return list;
}

// The n-th name of `list` ("" past its end).
inline std::string_view list_item(std::string_view list, int n) {
  for (int i = 0; i < n && !list.empty(); ++i) {
    const std::size_t comma = list.find(", ");
    list = comma == std::string_view::npos ? std::string_view() : list.substr(comma + 2);
  }
  return list.substr(0, list.find(", "));
}

// True when `name` is one of the names of `list`.
inline bool listed(std::string_view list, std::string_view name) {
  for (int n = 0; !list_item(list, n).empty(); ++n)
    if (list_item(list, n) == name) return true;
  return false;
}

}  // namespace clothlab
