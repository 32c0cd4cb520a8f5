// JSON text is valid UTF-8 whatever the bytes of the paths in it (io/files/json_text.h).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/files/json_text.h"

namespace sonarcarve {
namespace {

TEST(JsonText, BytesThatAreNotUtf8BecomeTheReplacementCharacter) {
  const nlohmann::json j = {{"out", "runs/caf\xe9"}, {"mission", "m\xc3\xa9"}};
  const std::string text = jsonText(j, -1);
  EXPECT_EQ(text, "{\"mission\":\"m\xc3\xa9\",\"out\":\"runs/caf\xef\xbf\xbd\"}");
  EXPECT_EQ(nlohmann::json::parse(text)["out"], "runs/caf\xef\xbf\xbd");
  EXPECT_THROW((void)j.dump(), nlohmann::json::type_error);  // what the reports did before
}

}  // namespace
}  // namespace sonarcarve
