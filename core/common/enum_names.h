// Names of enum values at the file, command-line and UI boundary: one table per enum, so that
// reading, writing, help texts and combo boxes all use the same words. An enum takes part by
// declaring, beside it, `constexpr const auto& enumNamesOf(E)` returning its table of
// EnumName<E>; toString, enumFromString<E> and enumNames<E> find it by argument-dependent
// lookup.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <type_traits>
#include <vector>

namespace sonarcarve {

template <typename E>
struct EnumName {
  E value;
  std::string_view name;
};

template <typename E>
concept NamedEnum = std::is_enum_v<E> && requires(E e) {
  enumNamesOf(e);
};

/// False for a value cast from a number that names nothing.
template <NamedEnum E>
constexpr bool hasName(E value) {
  for (const auto& n : enumNamesOf(value)) {
    if (n.value == value) {
      return true;
    }
  }
  return false;
}

template <NamedEnum E>
constexpr std::string_view toString(E value) {
  for (const auto& n : enumNamesOf(value)) {
    if (n.value == value) {
      return n.name;
    }
  }
  return "?";
}

template <NamedEnum E>
constexpr std::optional<E> enumFromString(std::string_view text) {
  for (const auto& n : enumNamesOf(E{})) {
    if (n.name == text) {
      return n.value;
    }
  }
  return std::nullopt;
}

/// The names alone, in the table's order.
template <NamedEnum E>
std::vector<std::string_view> enumNames() {
  std::vector<std::string_view> out;
  for (const auto& n : enumNamesOf(E{})) {
    out.push_back(n.name);
  }
  return out;
}

}  // namespace sonarcarve
