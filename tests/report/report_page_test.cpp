// The report page (report/report_page.hpp, report_frames.hpp): RFC 4648 base64, data inlined
// so no "</" ends the script early, and a walk's stick.csv read into frames.
#include <gtest/gtest.h>

#include "config/config_error.hpp"
#include "io/io_test_dir.hpp"
#include "report/report_frames.hpp"
#include "report/report_page.hpp"

namespace gaitopt::report {
namespace {

TEST(Base64, MatchesTheTestVectorsOfRfc4648) {
  const std::vector<std::pair<std::string, std::string>> vectors = {{"", ""},
                                                                    {"f", "Zg=="},
                                                                    {"fo", "Zm8="},
                                                                    {"foo", "Zm9v"},
                                                                    {"foob", "Zm9vYg=="},
                                                                    {"fooba", "Zm9vYmE="},
                                                                    {"foobar", "Zm9vYmFy"}};
  for (const auto& [text, encoded] : vectors) EXPECT_EQ(base64(text), encoded) << text;
  EXPECT_EQ(base64(std::string("\xff\x00\x10", 3)), "/wAQ");
}

TEST(ReportPage, InlinedDataCannotCloseTheScript) {
  ReportContent c;
  c.title = "</script><b>x";
  const std::string page = renderReportPage(c);
  EXPECT_EQ(page.find("</script><b>"), std::string::npos);
  EXPECT_NE(page.find("<\\/script><b>x"), std::string::npos);
  EXPECT_EQ(page.find("/*GAITOPT_REPORT_DATA*/null"), std::string::npos);
}

using StickCsv = io::test::IoTest;

TEST_F(StickCsv, RowsOfOneTimeAreOneFrame) {
  put(path("stick.csv"),
      "t,step,link,x0,y0,x1,y1,phase\n"
      "0,1,1,0,0,0.1,0.4,SSP\n0,1,2,0.1,0.4,0,0.8,SSP\n"
      "0.05,2,1,0.5,0,0.6,0.4,DSP\n0.05,2,2,0.6,0.4,0.5,0.8,DSP\n");
  const auto frames = readStickCsv(path("stick.csv"));
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1].t, 0.05);
  EXPECT_EQ(frames[1].step, 2);
  EXPECT_EQ(frames[1].phase, gaits::Phase::kDsp);
  ASSERT_EQ(frames[1].links.size(), 2u);
  EXPECT_EQ(frames[1].links[1], (std::array<double, 4>{0.6, 0.4, 0.5, 0.8}));
}

TEST_F(StickCsv, AFrameWithAMissingLinkIsRefused) {
  put(path("stick.csv"),
      "t,step,link,x0,y0,x1,y1,phase\n0,1,1,0,0,0.1,0.4,SSP\n0.05,1,2,0,0,0.1,0.4,SSP\n");
  EXPECT_THROW(readStickCsv(path("stick.csv")), config::ConfigError);
}

}  // namespace
}  // namespace gaitopt::report
