// Helpers that bind a parameter record to its member: row<&SolverSpec::dt>({...}) fills the
// record's section, kind, count and its read / values / address functions from the member's
// type, so a record names its key once and its member once. Used by parameters.cpp only.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "sim/scene/name_list.hpp"
#include "sim/scene/parameter_keys.hpp"
#include "sim/scene/parameters.hpp"
#include "sim/scene/scene.hpp"
#include "sim/scene/toml_reader.hpp"

namespace clothlab::binding {

// The ranges the table's records use most.
inline constexpr Range kPositive{0.0, Range::kInf, true, false};
inline constexpr Range kNonNegative{0.0, Range::kInf, false, false};
inline constexpr Range kUnit{0.0, 1.0, false, false};
constexpr Range between(double lo, double hi) {
  return Range{lo, hi, false, false};
}

template <class T>
struct Unwrap {
  using type = T;
};
template <class T>
struct Unwrap<std::optional<T>> {
  using type = T;
};

template <class T>
struct ArraySize : std::integral_constant<int, 1> {};
template <class T, std::size_t N>
struct ArraySize<std::array<T, N>> : std::integral_constant<int, int(N)> {};

// Reads the value the reader stands on into member M, by the member's type.
template <auto M>
void read_value(TomlReader& in, void* object) {
  using T = typename Unwrap<TypeOf<M>>::type;
  auto& member = object_of<M>(object).*M;
  const toml::node& n = in.node();
  if constexpr (std::is_same_v<T, double>) {
    member = in.number(n, in.key());
  } else if constexpr (std::is_same_v<T, int>) {
    member = in.small_integer(n, in.key());
  } else if constexpr (std::is_same_v<T, bool>) {
    member = in.boolean(n, in.key());
  } else if constexpr (std::is_same_v<T, std::string>) {
    member = in.text(n, in.key());
  } else if constexpr (std::is_same_v<T, std::array<double, ArraySize<T>::value>>) {
    member = in.numbers<ArraySize<T>::value>(n, in.key());
  } else {
    static_assert(std::is_same_v<T, std::array<int, ArraySize<T>::value>>);
    member = in.integers<ArraySize<T>::value>(n, in.key());
  }
}

// A text member, read-only (validate_scene checks it against the record's choices).
template <auto M>
const std::string* text_of(const void* object) {
  return &(static_cast<const StructOf<M>*>(object)->*M);
}

// The numbers validate_scene checks (none for text and booleans; none for an absent optional).
template <auto M>
int values_of(const void* object, double* out) {
  const auto& member = static_cast<const StructOf<M>*>(object)->*M;
  using T = TypeOf<M>;
  if constexpr (std::is_same_v<T, typename Unwrap<T>::type>) {
    if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, std::string>) {
      return 0;
    } else if constexpr (ArraySize<T>::value == 1) {
      out[0] = static_cast<double>(member);
      return 1;
    } else {
      for (int n = 0; n < ArraySize<T>::value; ++n) out[n] = static_cast<double>(member[n]);
      return ArraySize<T>::value;
    }
  } else {
    if (!member) return 0;
    using V = typename Unwrap<T>::type;
    if constexpr (ArraySize<V>::value == 1) {
      out[0] = *member;
      return 1;
    } else {
      for (int n = 0; n < ArraySize<V>::value; ++n) out[n] = (*member)[n];
      return ArraySize<V>::value;
    }
  }
}

template <class T>
constexpr ValueKind kind_of() {
  if constexpr (std::is_same_v<T, double>) return ValueKind::number;
  if constexpr (std::is_same_v<T, int>) return ValueKind::integer;
  if constexpr (std::is_same_v<T, bool>) return ValueKind::boolean;
  if constexpr (std::is_same_v<T, std::string>) return ValueKind::text;
  if constexpr (std::is_same_v<T, std::array<double, ArraySize<T>::value>>)
    return ValueKind::numbers;
  if constexpr (std::is_same_v<T, std::array<int, ArraySize<T>::value>>) return ValueKind::integers;
}

// A plain value: number, integer, boolean, text or a fixed array of them.
template <auto M>
Parameter row(Parameter p) {
  using T = typename Unwrap<TypeOf<M>>::type;
  p.section = section_of<StructOf<M>>();
  p.kind = kind_of<T>();
  p.count = ArraySize<T>::value;
  p.read = &read_value<M>;
  p.values = &values_of<M>;
  p.address = &address_of<M>;
  if constexpr (std::is_same_v<T, std::string> && std::is_same_v<T, TypeOf<M>>)
    p.text = &text_of<M>;
  p.optional = !std::is_same_v<T, TypeOf<M>>;
  return p;
}

// A string literal usable as a template argument (the noun of a choice's messages).
template <std::size_t N>
struct Text {
  char chars[N];
  constexpr Text(const char (&s)[N]) {
    for (std::size_t i = 0; i < N; ++i) chars[i] = s[i];
  }
};

template <auto M, auto& Names, Text What>
void read_choice(TomlReader& in, void* object) {
  object_of<M>(object).*M = in.choice(in.node(), in.key(), Names, What.chars);
}

// "a, b, c": the spellings of an enum's name table, made once.
template <auto& Names>
std::string_view joined_names() {
  static const std::string names =
      comma_list(Names, [](const auto& entry) { return std::string_view(entry.second); });
  return names;
}

template <auto M, auto& Names>
int choice_index(const void* object) {
  const auto value = static_cast<const StructOf<M>*>(object)->*M;
  for (std::size_t i = 0; i < Names.size(); ++i)
    if (Names[i].first == value) return static_cast<int>(i);
  return -1;
}

template <auto M, auto& Names>
void choose(void* object, int index) {
  object_of<M>(object).*M = Names[std::size_t(index)].first;
}

// One of a fixed list of names, read into an enum member.
template <auto M, auto& Names, Text What>
Parameter choice_row(Parameter p) {
  p.section = section_of<StructOf<M>>();
  p.kind = ValueKind::choice;
  p.choices = joined_names<Names>();
  p.read = &read_choice<M, Names, What>;
  p.address = &address_of<M>;
  p.choice_index = &choice_index<M, Names>;
  p.choose = &choose<M, Names>;
  return p;
}

template <auto M, Section Child>
void read_table(TomlReader& in, void* object) {
  in.read_section(in.table(in.node(), in.key()), in.key(), Child, &(object_of<M>(object).*M));
}

// A sub-table read into the struct member M.
template <auto M, Section Child>
Parameter table_row(Parameter p) {
  p.section = section_of<StructOf<M>>();
  p.kind = ValueKind::table;
  p.child = Child;
  p.read = &read_table<M, Child>;
  p.address = &address_of<M>;
  return p;
}

template <auto M, Section Child, Text What>
void read_tables(TomlReader& in, void* object) {
  in.read_tables(in.node(), in.key(), What.chars, Child, object_of<M>(object).*M);
}

// An array of tables ([[colliders]]) read into the vector member M.
template <auto M, Section Child, Text What>
Parameter tables_row(Parameter p) {
  p.section = section_of<StructOf<M>>();
  p.kind = ValueKind::tables;
  p.child = Child;
  p.read = &read_tables<M, Child, What>;
  p.address = &address_of<M>;
  return p;
}

// A key with a form of its own, read by a function of special_values.cpp; M is the member it
// fills (for the panel and for key_of).
template <auto M>
Parameter special_row(void (*read)(TomlReader&, void*), Parameter p,
                      int (*values)(const void*, double*) = nullptr) {
  p.section = section_of<StructOf<M>>();
  p.kind = ValueKind::special;
  p.read = read;
  p.values = values;
  p.address = &address_of<M>;
  return p;
}

}  // namespace clothlab::binding
