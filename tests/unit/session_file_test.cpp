// Sessions are recognised by what they say they are, not by their name.
#include <gtest/gtest.h>

#include "io/session_file.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

TEST(SessionFile, IsRecognisedByItsContentWhateverItsName) {
  test::ScratchDir dir;
  Session session;
  session.mission = test::exampleMission().string();
  const auto renamed = dir.path() / "survey notes.txt";
  saveSession(session, renamed);
  EXPECT_TRUE(looksLikeSessionFile(renamed));
  EXPECT_EQ(loadSession(renamed).mission, session.mission);

  EXPECT_FALSE(looksLikeSessionFile(test::exampleMission() / "mission.yaml"));
  EXPECT_FALSE(looksLikeSessionFile(test::exampleMission()));  // a folder
  EXPECT_FALSE(looksLikeSessionFile(dir.path() / "missing.sonarcarve"));
  const auto empty = dir.path() / "empty.sonarcarve";
  test::writeText(empty, "");
  EXPECT_FALSE(looksLikeSessionFile(empty));
}

}  // namespace
}  // namespace sonarcarve
