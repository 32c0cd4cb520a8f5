// What a pickle holds once decoded (io/pickle/pickle_reader.h): the few Python and numpy types
// a HoloOcean / NeuSIS frame file holds, and nothing that runs code. A numpy array is kept as
// its dtype, shape and raw bytes; numpyElements() gives its elements as doubles.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace sonarcarve::pickle {

/// A numpy dtype of numbers: kind 'f' (float), 'i' (signed), 'u' (unsigned) or 'b' (bool), its
/// size in bytes, and its byte order.
struct NumpyDtype {
  char kind = 0;
  int item_bytes = 0;
  bool big_endian = false;
  std::string text;  ///< as numpy wrote it: "f4", "<f8", "u1"
};

struct NumpyArray {
  NumpyDtype dtype;
  std::vector<std::int64_t> shape;
  bool fortran_order = false;
  std::string data;    ///< the elements' bytes, dtype.item_bytes each
  bool built = false;  ///< the state (shape, dtype, data) was given
};

enum class Kind { None, Bool, Int, Float, Text, Bytes, List, Tuple, Dict, Global, Dtype, Array };

struct Value;
using ValuePtr = std::shared_ptr<Value>;

struct Value {
  Kind kind = Kind::None;
  bool boolean = false;
  std::int64_t integer = 0;
  double number = 0.0;
  std::string text;             ///< Text (UTF-8), Bytes, or a Global's "module.name"
  std::vector<ValuePtr> items;  ///< List and Tuple items; a Dict's keys and values in turn
  NumpyDtype dtype;
  NumpyArray array;
  int height = 0;       ///< levels of containers below and including this one
  bool placed = false;  ///< held by a container: no longer changed
};

/// The kind's name for messages: "list", "numpy array".
const char* kindName(Kind kind);

/// The value of a Dict's text key `key`, or nullptr.
const Value* dictItem(const Value& dict, std::string_view key);

/// The array's elements as doubles, in C order (the last index varies fastest, whatever the
/// array's own order).
std::vector<double> numpyElements(const NumpyArray& array);

}  // namespace sonarcarve::pickle
