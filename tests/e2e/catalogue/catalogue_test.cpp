// The bad-input catalogue as GoogleTest cases: one test per case, named by its class and case.
#include "e2e/catalogue/catalogue.h"

namespace sonarcarve::test {

namespace {

class Catalogue : public ::testing::TestWithParam<CatalogueCase> {};

TEST_P(Catalogue, AnswersAsDocumented) {
  runCatalogueCase(GetParam());
}

std::string nameOf(const ::testing::TestParamInfo<CatalogueCase>& info) {
  return info.param.name;
}

INSTANTIATE_TEST_SUITE_P(NotAFile, Catalogue, ::testing::ValuesIn(fileKindCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(Content, Catalogue, ::testing::ValuesIn(contentCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(Limits, Catalogue, ::testing::ValuesIn(limitCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(Outputs, Catalogue, ::testing::ValuesIn(outputCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(Oculus, Catalogue, ::testing::ValuesIn(oculusCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(Readers, Catalogue, ::testing::ValuesIn(readerCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(Bags, Catalogue, ::testing::ValuesIn(bagCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(Geo, Catalogue, ::testing::ValuesIn(geoCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(Bounds, Catalogue, ::testing::ValuesIn(boundCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(Sense, Catalogue, ::testing::ValuesIn(senseCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(Messages, Catalogue, ::testing::ValuesIn(messageCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(FailedRuns, Catalogue, ::testing::ValuesIn(failedRunCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(RecordedSonar, Catalogue, ::testing::ValuesIn(recordedSonarCases()),
                         nameOf);
INSTANTIATE_TEST_SUITE_P(Paths, Catalogue, ::testing::ValuesIn(pathCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(MappedBounds, Catalogue, ::testing::ValuesIn(mappedBoundCases()), nameOf);
INSTANTIATE_TEST_SUITE_P(HoloOcean, Catalogue, ::testing::ValuesIn(holoOceanCases()), nameOf);

}  // namespace
}  // namespace sonarcarve::test
