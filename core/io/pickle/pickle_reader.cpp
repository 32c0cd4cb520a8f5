#include "io/pickle/pickle_reader.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <map>
#include <optional>

#include "common/error.h"
#include "io/files/input_file.h"

namespace sonarcarve::pickle {
namespace {

// The opcodes read (Python's Lib/pickle.py names them; protocols 2 to 5 write these).
enum Op : unsigned char {
  kMark = '(',
  kStop = '.',
  kPop = '0',
  kPopMark = '1',
  kBinFloat = 'G',
  kBinInt = 'J',
  kBinInt1 = 'K',
  kBinInt2 = 'M',
  kNone = 'N',
  kReduce = 'R',
  kBinString = 'T',
  kShortBinString = 'U',
  kBinUnicode = 'X',
  kAppend = 'a',
  kBuild = 'b',
  kGlobal = 'c',
  kDict = 'd',
  kEmptyDict = '}',
  kAppends = 'e',
  kBinGet = 'h',
  kLongBinGet = 'j',
  kList = 'l',
  kEmptyList = ']',
  kBinPut = 'q',
  kLongBinPut = 'r',
  kSetItem = 's',
  kTuple = 't',
  kEmptyTuple = ')',
  kSetItems = 'u',
  kBinBytes = 'B',
  kShortBinBytes = 'C',
  kProto = 0x80,
  kTuple1 = 0x85,
  kTuple2 = 0x86,
  kTuple3 = 0x87,
  kNewTrue = 0x88,
  kNewFalse = 0x89,
  kLong1 = 0x8a,
  kShortBinUnicode = 0x8c,
  kBinUnicode8 = 0x8d,
  kBinBytes8 = 0x8e,
  kStackGlobal = 0x93,
  kMemoize = 0x94,
  kFrame = 0x95,
  kByteArray8 = 0x96,
};

// What a global allowed by name does when REDUCE calls it.
enum class Callable { Reconstruct, NdarrayClass, DtypeClass, CodecsEncode, FromBuffer, Scalar };

std::optional<Callable> allowedGlobal(const std::string& name) {
  static const std::map<std::string, Callable, std::less<>> allowed{
      {"numpy.core.multiarray._reconstruct", Callable::Reconstruct},
      {"numpy._core.multiarray._reconstruct", Callable::Reconstruct},
      {"numpy.ndarray", Callable::NdarrayClass},
      {"numpy.dtype", Callable::DtypeClass},
      {"_codecs.encode", Callable::CodecsEncode},
      {"numpy.core.numeric._frombuffer", Callable::FromBuffer},
      {"numpy._core.numeric._frombuffer", Callable::FromBuffer},
      {"numpy.core.multiarray.scalar", Callable::Scalar},
      {"numpy._core.multiarray.scalar", Callable::Scalar},
  };
  const auto it = allowed.find(name);
  return it == allowed.end() ? std::nullopt : std::optional<Callable>(it->second);
}

std::string opcodeText(unsigned char op) {
  static const char* hex = "0123456789abcdef";
  std::string text = "0x";
  text += hex[op >> 4];
  text += hex[op & 15];
  if (op >= 0x20 && op < 0x7f) {
    text += std::string(" '") + static_cast<char>(op) + "'";
  }
  return text;
}

// "f4", "<f8", "|u1", "b1": a dtype of numbers, or nothing.
std::optional<NumpyDtype> parseDtype(const std::string& text) {
  std::string_view t = text;
  NumpyDtype dtype;
  dtype.text = text;
  if (!t.empty() && (t[0] == '<' || t[0] == '>' || t[0] == '|' || t[0] == '=')) {
    dtype.big_endian = t[0] == '>';
    t.remove_prefix(1);
  }
  if (t.size() != 2 || t[1] < '1' || t[1] > '8') {
    return std::nullopt;
  }
  dtype.kind = t[0];
  dtype.item_bytes = t[1] - '0';
  const int n = dtype.item_bytes;
  const bool whole = n == 1 || n == 2 || n == 4 || n == 8;
  const bool ok = (dtype.kind == 'f' && (n == 4 || n == 8)) ||
                  ((dtype.kind == 'i' || dtype.kind == 'u') && whole) ||
                  (dtype.kind == 'b' && n == 1);
  return ok ? std::optional<NumpyDtype>(dtype) : std::nullopt;
}

class Decoder {
 public:
  Decoder(std::string_view bytes, const std::string& source) : bytes_(bytes), source_(source) {}

  ValuePtr run() {
    if (bytes_.empty()) {
      throw Error(source_, "", "empty file: expected a pickle (protocol 2 to 5)");
    }
    while (pos_ < bytes_.size()) {
      op_at_ = pos_;
      op_ = static_cast<unsigned char>(bytes_[pos_++]);
      if (op_ == kStop) {
        return pop();
      }
      step();
    }
    throw Error(source_, bytePlace(bytes_.size()),
                "the pickle ends before its STOP opcode: expected more bytes (a file cut short?)");
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(source_, bytePlace(op_at_), "opcode " + opcodeText(op_) + ": " + what);
  }

  std::string_view take(std::uint64_t n) {
    const std::uint64_t left = bytes_.size() - pos_;
    if (n > left) {
      fail("needs " + std::to_string(n) + " bytes but only " + std::to_string(left) +
           " are left in the file (cut short, or a length that is not one)");
    }
    const std::string_view part = bytes_.substr(pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return part;
  }

  std::uint64_t unsignedLE(int n) {
    const std::string_view b = take(static_cast<std::uint64_t>(n));
    std::uint64_t v = 0;
    for (int i = n; i-- > 0;) {
      v = (v << 8) | static_cast<unsigned char>(b[static_cast<std::size_t>(i)]);
    }
    return v;
  }

  // Counts an object made or held once more by a container (a memo reference held a million
  // times costs memory as a million objects do).
  void count() {
    if (++objects_ > kMaxObjects) {
      fail("more than " + std::to_string(kMaxObjects) +
           " objects: expected a sonar frame's pickle, which holds a few dozen");
    }
  }

  ValuePtr make(Kind kind) {
    count();
    auto value = std::make_shared<Value>();
    value->kind = kind;
    if (kind == Kind::List || kind == Kind::Tuple || kind == Kind::Dict) {
      value->height = 1;
    }
    return value;
  }

  void push(ValuePtr value) {
    if (stack_.size() >= kMaxStack) {
      fail("more than " + std::to_string(kMaxStack) + " items on the stack");
    }
    stack_.push_back(std::move(value));
  }

  std::size_t floor() const { return marks_.empty() ? 0 : marks_.back(); }

  ValuePtr pop() {
    if (stack_.size() <= floor()) {
      fail("expected a value on the stack, found none");
    }
    ValuePtr top = std::move(stack_.back());
    stack_.pop_back();
    return top;
  }

  const ValuePtr& top() const {
    if (stack_.size() <= floor()) {
      fail("expected a value on the stack, found none");
    }
    return stack_.back();
  }

  std::vector<ValuePtr> popMark() {
    if (marks_.empty()) {
      fail("expected a MARK before it, found none");
    }
    const std::size_t mark = marks_.back();
    marks_.pop_back();
    std::vector<ValuePtr> items(stack_.begin() + static_cast<std::ptrdiff_t>(mark), stack_.end());
    stack_.resize(mark);
    return items;
  }

  // Puts `item` into `container`: refuses a loop and nesting past the limit.
  void place(Value& container, const ValuePtr& item) {
    if (item.get() == &container) {
      fail(std::string("a ") + kindName(container.kind) +
           " put inside itself (a reference loop through the memo): expected data without loops");
    }
    count();
    item->placed = true;
    container.height = std::max(container.height, item->height + 1);
    if (container.height > kMaxNesting) {
      fail("containers nested deeper than " + std::to_string(kMaxNesting) +
           " levels: expected a sonar frame's few levels");
    }
    container.items.push_back(item);
  }

  // The value on top, which this opcode changes: a `kind` not yet put inside another value.
  Value& changeable(Kind kind) {
    Value& target = *top();
    if (target.kind != kind) {
      fail(std::string("expected a ") + kindName(kind) + " to change, found a " +
           kindName(target.kind));
    }
    if (target.placed) {
      fail(std::string("changes a ") + kindName(kind) +
           " already put inside another value: Python's pickler never does (a reference loop?)");
    }
    return target;
  }

  ValuePtr container(Kind kind, const std::vector<ValuePtr>& items) {
    ValuePtr c = make(kind);
    for (const ValuePtr& item : items) {
      place(*c, item);
    }
    return c;
  }

  void pushScalar(Kind kind, std::int64_t integer, double number = 0.0) {
    ValuePtr v = make(kind);
    v->integer = integer;
    v->boolean = integer != 0;
    v->number = kind == Kind::Float ? number : static_cast<double>(integer);
    push(std::move(v));
  }

  void pushString(Kind kind, std::uint64_t length) {
    ValuePtr v = make(kind);
    v->text = std::string(take(length));
    push(std::move(v));
  }

  std::string line() {
    const std::size_t end = bytes_.find('\n', pos_);
    if (end == std::string_view::npos || end - pos_ > 256) {
      fail("expected a name of at most 256 characters ending with a newline");
    }
    std::string text(bytes_.substr(pos_, end - pos_));
    pos_ = end + 1;
    return text;
  }

  void pushGlobal(const std::string& module, const std::string& name) {
    const std::string full = module + "." + name;
    if (!allowedGlobal(full)) {
      fail("global '" + full +
           "' is not one this reader allows (only numpy's arrays, dtypes and scalars and "
           "_codecs.encode): nothing in a pickle is ever run");
    }
    ValuePtr v = make(Kind::Global);
    v->text = full;
    push(std::move(v));
  }

  void memoPut(std::uint64_t index) {
    if (memo_.size() >= kMaxObjects && !memo_.contains(index)) {
      fail("more than " + std::to_string(kMaxObjects) + " memo entries");
    }
    memo_[index] = top();
  }

  void memoGet(std::uint64_t index) {
    const auto it = memo_.find(index);
    if (it == memo_.end()) {
      fail("memo entry " + std::to_string(index) + " was never stored");
    }
    push(it->second);
  }

  const Value& arg(const std::vector<ValuePtr>& args, std::size_t i, Kind kind,
                   const std::string& what) {
    if (i >= args.size() || args[i]->kind != kind) {
      fail(what + ": expected argument " + std::to_string(i + 1) + " to be a " + kindName(kind));
    }
    return *args[i];
  }

  std::vector<std::int64_t> shapeOf(const Value& tuple, const std::string& what) {
    std::vector<std::int64_t> shape;
    for (const ValuePtr& d : tuple.items) {
      if (d->kind != Kind::Int || d->integer < 0) {
        fail(what + ": expected a shape of whole numbers >= 0");
      }
      shape.push_back(d->integer);
    }
    return shape;
  }

  // The array's shape and dtype must account for its bytes exactly.
  void checkArray(const NumpyArray& a) {
    std::uint64_t elements = 1;
    std::string shape_text;
    bool too_many = false;
    for (std::int64_t d : a.shape) {
      shape_text += (shape_text.empty() ? "" : " x ") + std::to_string(d);
      const auto n = static_cast<std::uint64_t>(d);
      if (n != 0 && elements > (std::uint64_t{1} << 62) / n) {
        too_many = true;
      } else {
        elements *= n;
      }
    }
    const std::uint64_t item = static_cast<std::uint64_t>(a.dtype.item_bytes);
    if (too_many || elements * item != a.data.size()) {
      fail("numpy array of shape " + (shape_text.empty() ? "()" : shape_text) + " of " +
           a.dtype.text + " needs " +
           (too_many ? "more than 2^62" : std::to_string(elements * item)) + " bytes but holds " +
           std::to_string(a.data.size()) + ": expected its shape to match its data");
    }
  }

  NumpyDtype dtypeFrom(const std::string& text) {
    const auto dtype = parseDtype(text);
    if (!dtype) {
      fail("numpy dtype '" + text +
           "': expected numbers (f4, f8, i1..i8, u1..u8, b1); strings and objects are not read");
    }
    return *dtype;
  }

  // _codecs.encode(text, 'latin1'): protocol 2's way of writing bytes.
  std::string latin1(const std::string& utf8) {
    std::string out;
    for (std::size_t i = 0; i < utf8.size(); ++i) {
      const auto c = static_cast<unsigned char>(utf8[i]);
      if (c < 0x80) {
        out += static_cast<char>(c);
      } else if ((c & 0xe0) == 0xc0 && i + 1 < utf8.size() && c <= 0xc3) {
        out +=
            static_cast<char>(((c & 0x03) << 6) | (static_cast<unsigned char>(utf8[++i]) & 0x3f));
      } else {
        fail("_codecs.encode: a character beyond Latin-1: expected bytes written as Latin-1 text");
      }
    }
    return out;
  }

  void reduce() {
    const ValuePtr args_value = pop();
    const ValuePtr callable = pop();
    if (callable->kind != Kind::Global || args_value->kind != Kind::Tuple) {
      fail(std::string("expected an allowed global and a tuple of arguments, found a ") +
           kindName(callable->kind) + " and a " + kindName(args_value->kind));
    }
    const std::vector<ValuePtr>& args = args_value->items;
    const std::string& name = callable->text;
    ValuePtr result;
    switch (*allowedGlobal(name)) {
      case Callable::Reconstruct: {
        const Value& cls = arg(args, 0, Kind::Global, name);
        if (cls.text != "numpy.ndarray") {
          fail(name + ": expected to make a numpy.ndarray, not a " + cls.text);
        }
        result = make(Kind::Array);
        break;
      }
      case Callable::DtypeClass:
        result = make(Kind::Dtype);
        result->dtype = dtypeFrom(arg(args, 0, Kind::Text, name).text);
        break;
      case Callable::CodecsEncode: {
        const std::string& encoding = arg(args, 1, Kind::Text, name).text;
        if (encoding != "latin1" && encoding != "latin-1") {
          fail(name + ": encoding '" + encoding + "': expected latin1");
        }
        result = make(Kind::Bytes);
        result->text = latin1(arg(args, 0, Kind::Text, name).text);
        break;
      }
      case Callable::FromBuffer: {
        result = make(Kind::Array);
        NumpyArray& a = result->array;
        const Kind buffer = !args.empty() ? args[0]->kind : Kind::None;
        a.data = arg(args, 0, buffer == Kind::Bytes ? Kind::Bytes : Kind::Bytes, name).text;
        a.dtype = arg(args, 1, Kind::Dtype, name).dtype;
        a.shape = shapeOf(arg(args, 2, Kind::Tuple, name), name);
        a.fortran_order = arg(args, 3, Kind::Text, name).text == "F";
        a.built = true;
        checkArray(a);
        break;
      }
      case Callable::Scalar: {
        NumpyArray a;
        a.dtype = arg(args, 0, Kind::Dtype, name).dtype;
        a.data = arg(args, 1, Kind::Bytes, name).text;
        checkArray(a);
        const double v = numpyElements(a).front();
        result = make(a.dtype.kind == 'f' ? Kind::Float : Kind::Int);
        result->number = v;
        result->integer = static_cast<std::int64_t>(v);
        break;
      }
      case Callable::NdarrayClass:
        fail("numpy.ndarray is called only through _reconstruct");
    }
    push(std::move(result));
  }

  void build() {
    const ValuePtr state = pop();
    Value& target = *top();
    if (target.kind != Kind::Array && target.kind != Kind::Dtype) {
      fail(std::string("BUILD of a ") + kindName(target.kind) +
           ": expected a numpy array or dtype");
    }
    if (target.placed || (target.kind == Kind::Array && target.array.built)) {
      fail(std::string("changes a ") + kindName(target.kind) + " already made");
    }
    if (state->kind != Kind::Tuple) {
      fail(std::string("expected the state of a ") + kindName(target.kind) +
           " as a tuple, found a " + kindName(state->kind));
    }
    const std::vector<ValuePtr>& s = state->items;
    if (target.kind == Kind::Dtype) {
      const std::string& order = arg(s, 1, Kind::Text, "numpy dtype state").text;
      target.dtype.big_endian = order == ">";
      return;
    }
    // (version, shape, dtype, is_fortran, data); numpy before 1.0 left out the version.
    const std::size_t first = s.size() == 5 ? 1 : 0;
    const std::string what = "numpy array state";
    NumpyArray& a = target.array;
    a.shape = shapeOf(arg(s, first, Kind::Tuple, what), what);
    a.dtype = arg(s, first + 1, Kind::Dtype, what).dtype;
    if (first + 2 >= s.size() ||
        (s[first + 2]->kind != Kind::Bool && s[first + 2]->kind != Kind::Int)) {
      fail(what + ": expected its order flag (a bool)");
    }
    a.fortran_order = s[first + 2]->integer != 0;
    a.data = arg(s, first + 3, Kind::Bytes, what).text;
    a.built = true;
    checkArray(a);
  }

  void step() {
    switch (op_) {
      case kProto: {
        const auto version = unsignedLE(1);
        if (version < 2 || version > 5) {
          fail("protocol " + std::to_string(version) + ": expected 2 to 5");
        }
        return;
      }
      case kFrame:
        if (unsignedLE(8) > bytes_.size() - pos_) {
          fail("a frame longer than the bytes left in the file");
        }
        return;
      case kMark:
        if (marks_.size() >= 2 * static_cast<std::size_t>(kMaxNesting)) {
          fail("marks nested deeper than " + std::to_string(2 * kMaxNesting) + " levels");
        }
        marks_.push_back(stack_.size());
        return;
      case kPop:
        pop();
        return;
      case kPopMark:
        popMark();
        return;
      case kEmptyDict:
        return push(make(Kind::Dict));
      case kEmptyList:
        return push(make(Kind::List));
      case kEmptyTuple:
        return push(make(Kind::Tuple));
      case kTuple:
        return push(container(Kind::Tuple, popMark()));
      case kList:
        return push(container(Kind::List, popMark()));
      case kDict: {
        const auto items = popMark();
        if (items.size() % 2 != 0) {
          fail("expected keys and values in pairs");
        }
        return push(container(Kind::Dict, items));
      }
      case kTuple1:
      case kTuple2:
      case kTuple3: {
        std::vector<ValuePtr> items(static_cast<std::size_t>(op_ - kTuple1 + 1));
        for (auto it = items.rbegin(); it != items.rend(); ++it) {
          *it = pop();
        }
        return push(container(Kind::Tuple, items));
      }
      case kAppend: {
        const ValuePtr item = pop();
        place(changeable(Kind::List), item);
        return;
      }
      case kAppends: {
        const auto items = popMark();
        Value& list = changeable(Kind::List);
        for (const ValuePtr& item : items) {
          place(list, item);
        }
        return;
      }
      case kSetItem: {
        const ValuePtr value = pop();
        const ValuePtr key = pop();
        Value& dict = changeable(Kind::Dict);
        place(dict, key);
        place(dict, value);
        return;
      }
      case kSetItems: {
        const auto items = popMark();
        if (items.size() % 2 != 0) {
          fail("expected keys and values in pairs");
        }
        Value& dict = changeable(Kind::Dict);
        for (const ValuePtr& item : items) {
          place(dict, item);
        }
        return;
      }
      case kNone:
        return push(make(Kind::None));
      case kNewTrue:
      case kNewFalse:
        return pushScalar(Kind::Bool, op_ == kNewTrue ? 1 : 0);
      case kBinInt1:
        return pushScalar(Kind::Int, static_cast<std::int64_t>(unsignedLE(1)));
      case kBinInt2:
        return pushScalar(Kind::Int, static_cast<std::int64_t>(unsignedLE(2)));
      case kBinInt:
        return pushScalar(Kind::Int, static_cast<std::int32_t>(unsignedLE(4)));
      case kLong1: {
        const auto n = static_cast<int>(unsignedLE(1));
        if (n > 8) {
          fail("an integer of " + std::to_string(n) + " bytes: expected at most 8");
        }
        std::uint64_t v = n == 0 ? 0 : unsignedLE(n);
        if (n > 0 && n < 8 && (v >> (8 * n - 1)) != 0) {
          v |= ~std::uint64_t{0} << (8 * n);  // negative: extend the sign
        }
        return pushScalar(Kind::Int, static_cast<std::int64_t>(v));
      }
      case kBinFloat: {
        const std::string_view b = take(8);
        std::uint64_t bits = 0;
        for (char c : b) {
          bits = (bits << 8) | static_cast<unsigned char>(c);  // big-endian
        }
        return pushScalar(Kind::Float, 0, std::bit_cast<double>(bits));
      }
      case kShortBinUnicode:
        return pushString(Kind::Text, unsignedLE(1));
      case kBinUnicode:
        return pushString(Kind::Text, unsignedLE(4));
      case kBinUnicode8:
        return pushString(Kind::Text, unsignedLE(8));
      case kShortBinBytes:
      case kShortBinString:
        return pushString(Kind::Bytes, unsignedLE(1));
      case kBinBytes:
        return pushString(Kind::Bytes, unsignedLE(4));
      case kBinString: {
        const auto length = static_cast<std::int32_t>(unsignedLE(4));
        if (length < 0) {
          fail("a negative length");
        }
        return pushString(Kind::Bytes, static_cast<std::uint64_t>(length));
      }
      case kBinBytes8:
      case kByteArray8:
        return pushString(Kind::Bytes, unsignedLE(8));
      case kMemoize:
        return memoPut(memo_.size());
      case kBinPut:
        return memoPut(unsignedLE(1));
      case kLongBinPut:
        return memoPut(unsignedLE(4));
      case kBinGet:
        return memoGet(unsignedLE(1));
      case kLongBinGet:
        return memoGet(unsignedLE(4));
      case kGlobal: {
        const std::string module = line();
        return pushGlobal(module, line());
      }
      case kStackGlobal: {
        const ValuePtr name = pop();
        const ValuePtr module = pop();
        if (name->kind != Kind::Text || module->kind != Kind::Text) {
          fail("expected a module and a name as strings");
        }
        return pushGlobal(module->text, name->text);
      }
      case kReduce:
        return reduce();
      case kBuild:
        return build();
      default:
        fail(
            "not an opcode this reader accepts (it reads protocols 2 to 5's dicts, lists, "
            "tuples, numbers, strings, bytes and numpy arrays, and runs nothing)");
    }
  }

  std::string_view bytes_;
  const std::string& source_;
  std::size_t pos_ = 0;
  std::size_t op_at_ = 0;
  unsigned char op_ = 0;
  std::vector<ValuePtr> stack_;
  std::vector<std::size_t> marks_;
  std::map<std::uint64_t, ValuePtr> memo_;
  std::size_t objects_ = 0;
};

}  // namespace

ValuePtr decodePickle(std::string_view bytes, const std::string& source) {
  return Decoder(bytes, source).run();
}

ValuePtr readPickleFile(const std::filesystem::path& path) {
  const std::string bytes = readInputFile(path, "pickle file", kMaxPickleFileBytes);
  return decodePickle(bytes, path.string());
}

}  // namespace sonarcarve::pickle
