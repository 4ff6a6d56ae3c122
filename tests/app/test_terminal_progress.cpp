// The progress bar of the long commands: drawn in place on a terminal at most ten times a second,
// ended by a newline; nothing at all elsewhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "app/terminal_progress.h"

namespace gps {
namespace {

int count(const std::string& text, char c) { return int(std::count(text.begin(), text.end(), c)); }

TEST(TerminalProgress, DrawsOneLineInPlaceAtMostTenTimesASecond) {
  std::ostringstream out;
  double now = 100;
  {
    TerminalProgress bar("simplifying", out, true, [&] { return now; });
    bar.update(0);
    EXPECT_EQ(out.str(), "\rsimplifying [                              ]   0%    0.0 s");
    now = 100.05;
    bar.update(0.2);  // a twentieth of a second later: not redrawn
    EXPECT_EQ(count(out.str(), '\r'), 1);
    now = 101.5;
    const ProgressReport report = bar.report();
    EXPECT_TRUE(report(0.5));  // never asks the work to stop
    EXPECT_EQ(count(out.str(), '\r'), 2);
    EXPECT_NE(out.str().find("\rsimplifying [###############               ]  50%    1.5 s"), std::string::npos)
        << out.str();
    now = 102;
    bar.finish();
    bar.update(0.7);  // after finish: nothing
    bar.finish();
  }
  const std::string s = out.str();
  EXPECT_EQ(count(s, '\r'), 3) << s;
  EXPECT_EQ(count(s, '\n'), 1) << s;
  EXPECT_TRUE(s.ends_with("\rsimplifying [##############################] 100%    2.0 s\n")) << s;
}

TEST(TerminalProgress, EndsTheLineOfWorkThatStoppedShort) {
  std::ostringstream out;
  double now = 0;
  {
    TerminalProgress bar("repairing", out, true, [&] { return now; });
    bar.update(0.25);
  }  // an error left the work at a quarter: the error goes on a line of its own
  EXPECT_EQ(out.str(), "\rrepairing [#######                       ]  25%    0.0 s\n");

  std::ostringstream never_drawn;
  { TerminalProgress bar("repairing", never_drawn, true, [&] { return now; }); }
  EXPECT_EQ(never_drawn.str(), "");
}

TEST(TerminalProgress, ClearsItsLineForOtherOutputAndRedrawsAtOnce) {
  std::ostringstream out;
  double now = 0;
  {
    TerminalProgress bar("fitting", out, true, [&] { return now; });
    bar.update(0.1);
    const size_t width = out.str().size() - 1;  // less the '\r'
    bar.clear();
    EXPECT_EQ(out.str().substr(width + 1), "\r" + std::string(width, ' ') + "\r");
    out.str("");
    bar.clear();  // nothing drawn since
    EXPECT_EQ(out.str(), "");
    bar.update(0.2);  // at the same moment, yet drawn: the line was blank
    EXPECT_EQ(out.str(), "\rfitting [######                        ]  20%    0.0 s");
    out.str("");
    bar.clear();
  }  // a blank line needs no newline
  EXPECT_EQ(out.str().find('\n'), std::string::npos);
}

TEST(TerminalProgress, WritesNothingWhereNotShown) {
  std::ostringstream out;
  double now = 0;
  {
    TerminalProgress bar("fitting", out, false, [&] { return now; });
    for (int k = 0; k <= 10; ++k, now += 1) bar.update(k / 10.0);
    EXPECT_TRUE(bar.report()(0.5));
    bar.finish();
  }
  EXPECT_EQ(out.str(), "");
}

TEST(TerminalProgress, ClampsTheFractionItIsGiven) {
  std::ostringstream out;
  double now = 0;
  TerminalProgress bar("tessellating", out, true, [&] { return now; });
  bar.update(-0.5);
  now = 1;
  bar.update(1.5);
  EXPECT_NE(out.str().find("[                              ]   0%"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("[##############################] 100%"), std::string::npos) << out.str();
}

}  // namespace
}  // namespace gps
