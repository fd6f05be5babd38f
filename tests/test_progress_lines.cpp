// test_progress_lines.cpp - a CAD load's progress lines (app/progress_lines.h): none into a
// pipe or a file however long the load takes, unless --progress asks; at a terminal (a pseudo
// terminal here) they are wanted; a reporter stays quiet for its quiet time on its clock (a
// clock the test moves, so a long load takes no time), then prints one line per stage and
// tenth; --progress is parsed, listed and reaches the scene settings.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

#include "app/cli.h"
#include "app/progress_lines.h"

namespace {

using Clock = std::chrono::steady_clock;

// What `out` holds from its start.
std::string contents(std::FILE* out) {
    std::fflush(out);
    std::rewind(out);
    std::string text;
    for (int c; (c = std::fgetc(out)) != EOF;) text += char(c);
    return text;
}

TEST(ProgressLines, APipeOrAFileGetsThemOnlyWhenAsked) {
    int ends[2];
    ASSERT_EQ(pipe(ends), 0);
    EXPECT_FALSE(app::progressLinesWanted(false, ends[1]));
    EXPECT_TRUE(app::progressLinesWanted(true, ends[1]));
    close(ends[0]);
    close(ends[1]);
    std::FILE* file = std::tmpfile();
    ASSERT_NE(file, nullptr);
    EXPECT_FALSE(app::progressLinesWanted(false, fileno(file)));
    EXPECT_TRUE(app::progressLinesWanted(true, fileno(file)));
    std::fclose(file);
}

TEST(ProgressLines, ATerminalGetsThem) {
    const int master = posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0)
        GTEST_SKIP() << "no pseudo terminal here";
    const int terminal = open(ptsname(master), O_RDWR | O_NOCTTY);
    ASSERT_GE(terminal, 0);
    EXPECT_TRUE(app::progressLinesWanted(false, terminal));
    close(terminal);
    close(master);
}

// The reporter on a clock the test sets: quiet for a second, then a line per stage and tenth.
TEST(ProgressLines, QuietForTheQuietTimeThenOneLinePerStageAndTenth) {
    Clock::time_point now{};
    std::FILE* out = std::tmpfile();
    ASSERT_NE(out, nullptr);
    const scene::CadProgress report =
        app::progressLines("part.step", out, app::progressQuiet, [&] { return now; });
    now += std::chrono::milliseconds(900);
    report("reading", 0.5);
    EXPECT_EQ(contents(out), "") << "a load shorter than a second prints nothing";
    now += std::chrono::seconds(5); // a long load, on this clock
    report("reading", 0.5);
    report("reading", 0.55); // the same tenth
    report("tessellating", 0.42);
    report("tessellating", 0.3); // backwards within a stage: nothing
    report("tessellating", 1.0);
    report("building", 0.0);
    EXPECT_EQ(contents(out), "idview: loading part.step: reading 50%\n"
                             "idview: loading part.step: tessellating 40%\n"
                             "idview: loading part.step: tessellating 100%\n"
                             "idview: loading part.step: building 0%\n");
    std::fclose(out);
}

// stderr as a file, as ctest and a log have it: no reporter at all unless asked, so no line
// however long the load; asked, a line from the start. `body` runs with stderr redirected.
std::string withStderrInAFile(const std::function<void()>& body) {
    std::fflush(stderr);
    const int kept = dup(STDERR_FILENO);
    std::FILE* file = std::tmpfile();
    if (kept < 0 || !file) return "cannot redirect stderr";
    dup2(fileno(file), STDERR_FILENO);
    body();
    std::fflush(stderr);
    dup2(kept, STDERR_FILENO);
    close(kept);
    std::string text = contents(file);
    std::fclose(file);
    return text;
}

TEST(ProgressLines, LoadsReportOnStderrInAFileOnlyWithProgress) {
    const std::string quiet = withStderrInAFile([] {
        const scene::CadProgress report = app::stderrProgress("part.step", false);
        EXPECT_FALSE(report) << "a reporter for a stderr no one reads";
    });
    EXPECT_EQ(quiet, "");
    const std::string asked = withStderrInAFile([] {
        const scene::CadProgress report = app::stderrProgress("part.step", true);
        ASSERT_TRUE(report);
        report("reading", 0.0); // at once: --progress waits for no second
    });
    EXPECT_EQ(asked, "idview: loading part.step: reading 0%\n");
}

TEST(ProgressLines, TheFlagReachesTheSceneSettings) {
    EXPECT_FALSE(app::SceneSettings{}.progress);
    EXPECT_FALSE(app::parseArgs(std::vector<std::string>{}).live.scene.progress);
    EXPECT_TRUE(
        app::parseArgs(std::vector<std::string>{"--headless", "--progress"}).live.scene.progress);
    EXPECT_NE(app::usage().find("--progress"), std::string::npos);
}

} // namespace
