#include "io/pickle/pickle_value.h"

#include <algorithm>
#include <cstring>

namespace sonarcarve::pickle {
namespace {

template <typename T>
double elementAs(const char* bytes, bool big_endian) {
  char ordered[sizeof(T)];
  std::memcpy(ordered, bytes, sizeof(T));
  if (big_endian) {
    std::reverse(ordered, ordered + sizeof(T));
  }
  T value;
  std::memcpy(&value, ordered, sizeof(T));
  return static_cast<double>(value);
}

double element(const NumpyDtype& dtype, const char* bytes) {
  const bool big = dtype.big_endian;
  switch (dtype.kind) {
    case 'f':
      return dtype.item_bytes == 4 ? elementAs<float>(bytes, big) : elementAs<double>(bytes, big);
    case 'b':
      return bytes[0] != 0 ? 1.0 : 0.0;
    case 'u':
      switch (dtype.item_bytes) {
        case 1:
          return elementAs<std::uint8_t>(bytes, big);
        case 2:
          return elementAs<std::uint16_t>(bytes, big);
        case 4:
          return elementAs<std::uint32_t>(bytes, big);
        default:
          return elementAs<std::uint64_t>(bytes, big);
      }
    default:
      switch (dtype.item_bytes) {
        case 1:
          return elementAs<std::int8_t>(bytes, big);
        case 2:
          return elementAs<std::int16_t>(bytes, big);
        case 4:
          return elementAs<std::int32_t>(bytes, big);
        default:
          return elementAs<std::int64_t>(bytes, big);
      }
  }
}

}  // namespace

const char* kindName(Kind kind) {
  switch (kind) {
    case Kind::None:
      return "None";
    case Kind::Bool:
      return "bool";
    case Kind::Int:
      return "int";
    case Kind::Float:
      return "float";
    case Kind::Text:
      return "str";
    case Kind::Bytes:
      return "bytes";
    case Kind::List:
      return "list";
    case Kind::Tuple:
      return "tuple";
    case Kind::Dict:
      return "dict";
    case Kind::Global:
      return "global";
    case Kind::Dtype:
      return "numpy dtype";
    case Kind::Array:
      return "numpy array";
  }
  return "value";
}

const Value* dictItem(const Value& dict, std::string_view key) {
  if (dict.kind != Kind::Dict) {
    return nullptr;
  }
  for (std::size_t i = 0; i + 1 < dict.items.size(); i += 2) {
    if (dict.items[i]->kind == Kind::Text && dict.items[i]->text == key) {
      return dict.items[i + 1].get();
    }
  }
  return nullptr;
}

std::vector<double> numpyElements(const NumpyArray& array) {
  const auto item = static_cast<std::size_t>(array.dtype.item_bytes);
  const std::size_t count = item == 0 ? 0 : array.data.size() / item;
  std::vector<double> out(count);
  const std::size_t dims = array.shape.size();
  if (!array.fortran_order || dims < 2) {
    for (std::size_t i = 0; i < count; ++i) {
      out[i] = element(array.dtype, array.data.data() + i * item);
    }
    return out;
  }
  // Fortran order: the first index varies fastest in the data.
  std::vector<std::size_t> index(dims, 0);
  for (std::size_t c = 0; c < count; ++c) {
    std::size_t offset = 0, stride = 1;
    for (std::size_t k = 0; k < dims; ++k) {
      offset += index[k] * stride;
      stride *= static_cast<std::size_t>(array.shape[k]);
    }
    out[c] = element(array.dtype, array.data.data() + offset * item);
    for (std::size_t k = dims; k-- > 0;) {  // the next C-order index
      if (++index[k] < static_cast<std::size_t>(array.shape[k])) {
        break;
      }
      index[k] = 0;
    }
  }
  return out;
}

}  // namespace sonarcarve::pickle
