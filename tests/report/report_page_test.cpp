// The report page (report/report_page.hpp, report_frames.hpp): RFC 4648 base64, user text
// inlined as data that neither ends the script nor opens markup, and a walk's stick.csv read
// into frames.
#include <algorithm>
#include <cctype>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

// User text that would end the script ("</script>") or send the HTML parser into its escaped
// states ("<!--", "<script"), which swallow the rest of the page, and an entity.
const std::string kHostile = "a<!--<script>b</script>c<SCRIPT>&amp;d";

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return text;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The data literal the page's script starts with ("const DATA = ...;").
std::string dataLiteral(const std::string& page) {
  const std::string start = "const DATA = ";
  const std::size_t from = page.find(start) + start.size();
  return page.substr(from, page.find(";\n", from) - from);
}

using ReportPage = io::test::IoTest;

TEST_F(ReportPage, UserTextStaysDataInsideTheScript) {
  put(path("sweep.csv"), "name,value\n" + kHostile + ",1\n");
  const std::string chart = "a<!--<script>&amp;.png";  // a file name holds no "/"
  put(path(chart), "png bytes");
  ReportContent c;
  c.title = c.kind = c.animation_note = kHostile;
  c.summary = {{kHostile, kHostile}};
  c.link_names = {kHostile};
  c.tables = {path("sweep.csv")};
  c.charts = {path(chart)};
  const std::string page = lowercase(renderReportPage(c));
  const std::string plain = lowercase(renderReportPage({}));
  // The template's tags and comments only: the data opened and closed none.
  EXPECT_EQ(count(page, "<script"), count(plain, "<script"));
  EXPECT_EQ(count(page, "</script"), count(plain, "</script"));
  EXPECT_EQ(count(page, "<!--"), count(plain, "<!--"));
  // The script block holding the data runs past all of it to the template's "</script".
  const std::string data = dataLiteral(renderReportPage(c));
  EXPECT_EQ(data.find_first_of("<>&"), std::string::npos) << data;
  const std::size_t block = page.rfind("<script", page.find("const data = "));
  EXPECT_GT(page.find("</script", block), page.find(lowercase(data)));

  const auto json = nlohmann::json::parse(data);
  EXPECT_EQ(json["title"], kHostile);
  EXPECT_EQ(json["kind"], kHostile);
  EXPECT_EQ(json["animation_note"], kHostile);
  EXPECT_EQ(json["summary"][kHostile], kHostile);
  EXPECT_EQ(json["link_names"][0], kHostile);
  EXPECT_EQ(json["tables"][0]["csv"], "name,value\n" + kHostile + ",1\n");
  EXPECT_EQ(json["charts"][0]["name"], chart);
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
