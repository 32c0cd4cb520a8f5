// The pickle decoder (io/pickle/pickle_reader.h) on pickles of every protocol HoloOcean's users
// write (the test writer, support/pickle_writer.h, writes them as Python 3 and numpy 1.x do),
// and on bad ones: empty, cut at every byte, a global outside the allow-list, bombs of nesting
// and of memo references, an array declaring more than it holds. Each bad one is refused with
// an Error naming the source, the byte and what was expected, quickly.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "common/error.h"
#include "io/pickle/pickle_reader.h"
#include "support/pickle_writer.h"

namespace sonarcarve {
namespace {

using pickle::decodePickle;
using namespace std::string_literals;
using test::PickleWriter;

// The message of the Error decoding `bytes` throws ("" if none).
std::string refusal(const std::string& bytes) {
  try {
    decodePickle(bytes, "frame.pkl");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string proto2(const std::string& body) {
  return std::string("\x80\x02", 2) + body;
}

class PickleProtocols : public ::testing::TestWithParam<int> {};

TEST_P(PickleProtocols, ADictOfArraysReadsBackElementForElement) {
  const int protocol = GetParam();
  // Values of float32: exact after the cast (halves and small integers).
  std::vector<double> image;
  for (int i = 0; i < 3 * 5; ++i) {
    image.push_back(0.5 * i - 1.0);
  }
  PickleWriter w(protocol);
  w.op('}').memoize().op('(');
  w.text("ImagingSonar").numpyArray(image, {3, 5});
  w.text("Wide").numpyArray({1e300, -2.5}, {2}, true);
  w.text("t").real(12.25);
  w.text("n").integer(-70000);
  const std::string bytes = w.op('u').finish();

  const pickle::ValuePtr v = decodePickle(bytes, "frame.pkl");
  ASSERT_EQ(v->kind, pickle::Kind::Dict);
  const pickle::Value* a = pickle::dictItem(*v, "ImagingSonar");
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->kind, pickle::Kind::Array);
  EXPECT_EQ(a->array.shape, (std::vector<std::int64_t>{3, 5}));
  EXPECT_EQ(a->array.dtype.kind, 'f');
  EXPECT_EQ(a->array.dtype.item_bytes, 4);
  EXPECT_EQ(pickle::numpyElements(a->array), image);
  const pickle::Value* wide = pickle::dictItem(*v, "Wide");
  ASSERT_NE(wide, nullptr);
  EXPECT_EQ(pickle::numpyElements(wide->array), (std::vector<double>{1e300, -2.5}));
  EXPECT_EQ(pickle::dictItem(*v, "t")->number, 12.25);
  EXPECT_EQ(pickle::dictItem(*v, "n")->integer, -70000);
}

INSTANTIATE_TEST_SUITE_P(Protocols, PickleProtocols, ::testing::Values(2, 3, 4, 5));

TEST(PickleReader, FortranOrderIsGivenInCOrder) {
  // The state tuple of a 2 x 3 array whose data is in Fortran order (columns first).
  PickleWriter w(3);
  w.reconstructedArray({2, 3}, "u1", "|", true, std::string("\x01\x04\x02\x05\x03\x06", 6));
  const pickle::ValuePtr v = decodePickle(w.finish(), "f.pkl");
  ASSERT_EQ(v->kind, pickle::Kind::Array);
  EXPECT_EQ(pickle::numpyElements(v->array), (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST(PickleReader, AnEmptyFileIsRefused) {
  EXPECT_NE(refusal("").find("frame.pkl: empty file: expected a pickle"), std::string::npos)
      << refusal("");
}

TEST(PickleReader, APickleCutAtAnyByteIsRefusedNamingTheByte) {
  PickleWriter w(4);
  w.op('}').memoize().text("PoseSensor").numpyArray(std::vector<double>(16, 1.0), {4, 4}).op('s');
  const std::string whole = w.finish();
  ASSERT_NO_THROW(decodePickle(whole, "frame.pkl"));
  for (std::size_t cut = 1; cut < whole.size(); ++cut) {
    const std::string message = refusal(whole.substr(0, cut));
    EXPECT_NE(message.find("frame.pkl: byte "), std::string::npos) << cut << ": " << message;
  }
  // Without a FRAME to declare its length (protocol 3), the cut shows at the end.
  const std::string unframed = PickleWriter(3).op('}').finish();
  EXPECT_NE(refusal(unframed.substr(0, unframed.size() - 1)).find("ends before its STOP opcode"),
            std::string::npos);
}

TEST(PickleReader, AGlobalOutsideTheAllowListIsRefusedAndNothingRuns) {
  // pickle.dumps of a class whose __reduce__ returns (os.system, ('echo hacked',)).
  const std::string bomb = proto2("cos\nsystem\nq\x00X\x0b\x00\x00\x00echo hackedq\x01\x85R."s);
  const std::string message = refusal(bomb);
  EXPECT_NE(message.find("frame.pkl: byte 2: opcode 0x63 'c': global 'os.system' is not one"),
            std::string::npos)
      << message;
  EXPECT_NE(refusal(proto2("c__builtin__\neval\n.")).find("'__builtin__.eval'"), std::string::npos);
  // STACK_GLOBAL (protocol 4) likewise.
  PickleWriter w(4);
  w.global("subprocess", "call");
  EXPECT_NE(refusal(w.finish()).find("global 'subprocess.call' is not one"), std::string::npos);
}

TEST(PickleReader, OpcodesOutsideTheDataOnesAreRefusedNamingThem) {
  EXPECT_NE(refusal(proto2("(i__main__\nX\n.")).find("byte 3: opcode 0x69 'i': not an opcode"),
            std::string::npos)
      << refusal(proto2("(i__main__\nX\n."));
  EXPECT_NE(refusal("\x80\x06.").find("protocol 6: expected 2 to 5"), std::string::npos);
  EXPECT_NE(refusal(proto2("N\x81.")).find("opcode 0x81"), std::string::npos);  // NEWOBJ
}

TEST(PickleReader, NestingBombsAreRefusedAtTheLimitQuickly) {
  const auto start = std::chrono::steady_clock::now();
  // A million TUPLE1 around an empty list: nested a million deep.
  const std::string tuples = proto2("]" + std::string(1000000, '\x85') + ".");
  EXPECT_NE(refusal(tuples).find("nested deeper than 64 levels"), std::string::npos)
      << refusal(tuples);
  // A million MARKs, each to become a list.
  const std::string lists = proto2(std::string(1000000, '(') + std::string(1000000, 'l') + ".");
  EXPECT_NE(refusal(lists).find("marks nested deeper than"), std::string::npos) << refusal(lists);
  // A list of 40000 empty lists is wide, not deep; a million of them are too many objects.
  std::string wide = proto2("]");
  for (int i = 0; i < 40000; ++i) {
    wide += "]a";
  }
  EXPECT_EQ(refusal(wide + "."), "") << "a wide list is not a deep one";
  for (int i = 40000; i < 1000000; ++i) {
    wide += "]a";
  }
  EXPECT_NE(refusal(wide + ".").find("more than 100000 objects"), std::string::npos);
  // One list held a million times through the memo: as many references.
  std::string held = proto2("]q\x00]"s);
  for (int batch = 0; batch < 1000; ++batch) {
    held += "(";
    for (int i = 0; i < 1000; ++i) {
      held += "h\x00"s;
    }
    held += "e";
  }
  EXPECT_NE(refusal(held + "."s).find("more than 100000 objects"), std::string::npos)
      << refusal(held + "."s);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5.0);
}

TEST(PickleReader, MemoReferenceLoopsAreRefused) {
  // l = []; l.append(l)
  EXPECT_NE(refusal(proto2("]q\x00h\x00\x61."s)).find("list put inside itself (a reference loop"),
            std::string::npos)
      << refusal(proto2("]q\x00h\x00\x61."s));
  // a = []; b = []; a.append(b); b.append(a): b is changed after it was put in a.
  const std::string two = proto2("]q\x00]q\x01\x61h\x01h\x00\x61."s);
  EXPECT_NE(refusal(two).find("changes a list already put inside another value"), std::string::npos)
      << refusal(two);
  // d = {}; d['k'] = d
  EXPECT_NE(refusal(proto2("}q\x00X\x01\x00\x00\x00kh\x00s."s)).find("dict put inside itself"),
            std::string::npos);
  EXPECT_NE(refusal(proto2("h\x07.")).find("memo entry 7 was never stored"), std::string::npos);
}

TEST(PickleReader, AnArrayDeclaringMoreThanItHoldsIsRefusedBeforeAllocating) {
  PickleWriter w(3);
  w.reconstructedArray({1000000000, 1000000000, 1000000000}, "f8", "<", false, "12345678");
  const std::string message = refusal(w.finish());
  EXPECT_NE(message.find("numpy array of shape 1000000000 x 1000000000 x 1000000000 of f8 needs "
                         "more than 2^62 bytes but holds 8"),
            std::string::npos)
      << message;
  // A bytes length past the end of the file: refused before it is read.
  const std::string huge = proto2(std::string("B\xff\xff\xff\x7f", 5) + "abc.");
  EXPECT_NE(refusal(huge).find("needs 2147483647 bytes but only 4 are left"), std::string::npos)
      << refusal(huge);
}

TEST(PickleReader, DtypesOtherThanNumbersAreRefused) {
  PickleWriter w(3);
  w.dtype("O8", "|");
  EXPECT_NE(refusal(w.finish()).find("numpy dtype 'O8': expected numbers"), std::string::npos);
}

}  // namespace
}  // namespace sonarcarve
