// The gpsurf command line, run as a user would: exit codes 0/1/2, one-line errors, files written.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include "core/io/mesh_io.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::gpsurf;
using test::run_command;

TEST(Cli, SampleInfoSubdivideInfer) {
  test::TempDir dir;
  const auto list = run_command(gpsurf("sample --list"));
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_NE(list.output.find("wirecube"), std::string::npos);
  EXPECT_EQ(run_command(gpsurf("sample cube -o " + dir.file("cube.ply"))).exit_code, 0);
  const auto info = run_command(gpsurf("info " + dir.file("cube.ply")));
  EXPECT_EQ(info.exit_code, 0);
  EXPECT_NE(info.output.find("vertices: 8"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("6 with 4 sides"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("extraordinary vertices: 8"), std::string::npos) << info.output;
  const auto sub =
      run_command(gpsurf("subdivide " + dir.file("cube.ply") + " -o " + dir.file("s.ply") + " --levels 2 --limit"));
  EXPECT_EQ(sub.exit_code, 0) << sub.output;
  EXPECT_EQ(read_mesh(dir.file("s.ply")).n_faces(), 96u);
  EXPECT_EQ(
      run_command(gpsurf("subdivide " + dir.file("cube.ply") + " -o " + dir.file("s.obj") + " --levels 1")).exit_code,
      0);
  EXPECT_EQ(read_mesh(dir.file("s.obj")).n_faces(), 24u);
  EXPECT_EQ(run_command(gpsurf("sample cone -o " + dir.file("cone.ply"))).exit_code, 0);
  EXPECT_EQ(run_command(gpsurf("subdivide " + dir.file("cone.ply") + " -o " + dir.file("l.ply") +
                               " --levels 2 --scheme loop --loop-beta warren"))
                .exit_code,
            0);
  // A mesh of triangles: Loop by default, as render and tessellate draw it, and info says so.
  EXPECT_EQ(run_command(gpsurf("subdivide " + dir.file("cone.ply") + " -o " + dir.file("auto.ply") + " --levels 2"))
                .exit_code,
            0);
  EXPECT_EQ(run_command(gpsurf("subdivide " + dir.file("cone.ply") + " -o " + dir.file("loop.ply") +
                               " --levels 2 --scheme loop"))
                .exit_code,
            0);
  EXPECT_EQ(read_mesh(dir.file("auto.ply")).n_faces(), 8u * 16u);
  EXPECT_EQ(read_mesh(dir.file("auto.ply")).covariances, read_mesh(dir.file("loop.ply")).covariances);
  const auto cone_info = run_command(gpsurf("info " + dir.file("cone.ply")));
  EXPECT_NE(cone_info.output.find("scheme: Loop"), std::string::npos) << cone_info.output;
  EXPECT_NE(cone_info.output.find("extraordinary vertices: 9 (by Loop's rules)"), std::string::npos)
      << cone_info.output;
  EXPECT_NE(info.output.find("scheme: Catmull-Clark"), std::string::npos) << info.output;
  EXPECT_EQ(run_command(gpsurf("infer " + dir.file("s.obj") + " -o " + dir.file("i.ply") + " --bias 0.1")).exit_code,
            0);
  EXPECT_EQ(
      run_command(gpsurf("infer " + dir.file("s.obj") + " -o " + dir.file("j.ply") + " --isotropic 0.3")).exit_code, 0);
  for (const char* cmd : {"info", "sample", "infer", "subdivide"})
    EXPECT_EQ(run_command(gpsurf(std::string(cmd) + " --help")).exit_code, 0) << cmd;
}

// Covariances that are subnormal (1e-310) or huge (1e308), ASCII or binary, and positions at ±1e308:
// every command refuses them with a message that says so, and writes nothing (never a file of NaNs
// that `gpsurf info` would refuse).
TEST(Cli, ValuesBeyondWhatTheMathCarriesAreRefusedAndNothingIsWritten) {
  test::TempDir dir;
  const auto ply = [](const std::string& format, double position, double variance) {
    std::string s = "ply\nformat " + format + " 1.0\nelement vertex 4\n";
    for (const char* p : {"x", "y", "z", "cxx", "cxy", "cxz", "cyy", "cyz", "czz"})
      s += std::string("property double ") + p + "\n";
    s += "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const double v[4][3] = {{0, 0, 0}, {position, 0, 0}, {1, 1, 0}, {0, -position, 0}};
    for (const auto& p : v) {
      const double values[9] = {p[0], p[1], p[2], variance, 0, 0, variance, 0, variance};
      if (format == "ascii") {
        std::ostringstream line;
        line.precision(17);
        for (const double x : values) line << x << ' ';
        s += line.str() + "\n";
      } else {
        s.append(reinterpret_cast<const char*>(values), sizeof values);
      }
    }
    s += format == "ascii" ? "4 0 1 2 3\n" : std::string("\x04\0\0\0\0\x01\0\0\0\x02\0\0\0\x03\0\0\0", 17);
    return s;
  };
  const std::vector<std::tuple<std::string, std::string, std::string>> inputs = {
      {"subnormal.ply", ply("ascii", 1, 1e-310), "covariance eigenvalue 1e-310 below 1e-100 (subnormal: underflows)"},
      {"subnormal_binary.ply", ply("binary_little_endian", 1, 1e-310), "(subnormal: underflows)"},
      {"huge.ply", ply("binary_little_endian", 1, 1e308), "covariance eigenvalue 1e+308 above 1e+100"},
      {"far.ply", ply("ascii", 1e308, 0.1), "vertex 1 has a coordinate 1e+308 beyond"},
      {"underflow.obj", "v 0 0 0\nv 1e-400 1 0\nv 1 0 0\nf 1 2 3\n", "line 2: '1e-400' underflows"},
  };
  for (const auto& [name, contents, expected] : inputs) {
    const std::string in = dir.write(name, contents);
    for (const std::string& cmd : {"info " + in, "subdivide " + in + " -o " + dir.file("s.ply") + " --levels 1",
                                   "tessellate " + in + " -o " + dir.file("t.ply") + " --depth 2 --level 2"}) {
      const auto r = run_command(gpsurf(cmd));
      EXPECT_EQ(r.exit_code, 1) << cmd << ": " << r.output;
      EXPECT_EQ(test::line_count(r.output), 1u) << cmd << ": " << r.output;
      EXPECT_NE(r.output.find(expected), std::string::npos) << cmd << ": " << r.output;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("s.ply")));
    EXPECT_FALSE(std::filesystem::exists(dir.file("t.ply")));
  }
}

TEST(Cli, UsageErrorsExitWithTwo) {
  test::TempDir dir;
  run_command(gpsurf("sample cube -o " + dir.file("cube.ply")));
  for (const std::string& args : std::vector<std::string>{
           "", "frobnicate", "sample teapot -o " + dir.file("t.ply"),
           "subdivide " + dir.file("cube.ply") + " -o " + dir.file("x.ply") + " --levels 9",
           "subdivide " + dir.file("cube.ply") + " -o " + dir.file("x.ply") + " --scheme butterfly",
           "infer " + dir.file("cube.ply") + " -o " + dir.file("x.ply") + " --bias -1", "sample cube"}) {
    const auto r = run_command(gpsurf(args));
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_EQ(test::line_count(r.output), 1u) << args << ": " << r.output;
  }
}

// An option a command would ignore is an error, and a range error is short.
TEST(Cli, IgnoredOptionsAndRangesAreShortErrors) {
  test::TempDir dir;
  run_command(gpsurf("sample cube -o " + dir.file("cube.ply")));
  const auto size = run_command(gpsurf("sample cube --size 5 -o " + dir.file("c.ply")));
  EXPECT_EQ(size.exit_code, 2) << size.output;
  EXPECT_NE(size.output.find("--size applies to grid, sphere and icosphere only"), std::string::npos) << size.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("c.ply")));
  EXPECT_EQ(run_command(gpsurf("sample sphere --size 500 -o " + dir.file("s.ply"))).exit_code, 0);
  const auto bias = run_command(gpsurf("infer " + dir.file("cube.ply") + " -o " + dir.file("x.ply") + " --bias 0"));
  EXPECT_EQ(bias.exit_code, 2) << bias.output;
  EXPECT_NE(bias.output.find("expected a number > 0, got '0'"), std::string::npos) << bias.output;
  EXPECT_LT(bias.output.size(), 160u) << bias.output;
  EXPECT_EQ(
      run_command(gpsurf("render " + dir.file("cube.ply") + " -o " + dir.file("r.png") + " --size 0x5")).exit_code, 2);
}

// Option values are read as written, in full and as the type they become: an empty text is not 0,
// 0x10 not 16, 010 not 8, 180.0001 is not shown as 180, and the message is ours, quoting the text
// (an empty value after '=' too, which CLI11 alone reports as a missing value).
TEST(Cli, OptionNumbersAreReadExactlyAsWritten) {
  test::TempDir dir;
  const std::string cube = dir.file("cube.ply"), out = dir.file("x.ply");
  run_command(gpsurf("sample cube -o " + cube));
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"infer " + cube + " -o " + out + " --crease-angle ''",
            "--crease-angle: expected a number from 0 to 180, got ''"},
           {"infer " + cube + " -o " + out + " --crease-angle=",
            "--crease-angle: expected a number from 0 to 180, got ''"},
           {"infer " + cube + " -o " + out + " --crease-angle=abc",
            "--crease-angle: expected a number from 0 to 180, got 'abc'"},
           {"infer " + cube + " -o " + out + " --crease-angle=181",
            "--crease-angle: expected a number from 0 to 180, got '181'"},
           {"infer " + cube + " -o " + out + " --crease-angle=nan",
            "--crease-angle: expected a number from 0 to 180, got 'nan'"},
           {"info " + cube + " --weld=", "--weld: expected a number >= 0, got ''"},
           {"simplify " + cube + " -o " + out + " --ratio=", "--ratio: expected a number > 0 and at most 1, got ''"},
           {"simplify " + cube + " -o " + out + " --vertices=",
            "--vertices: expected an integer from 4 to 1099511627776, got ''"},
           {"infer " + cube + " -o " + out + " --crease-angle 180.0001",
            "--crease-angle: expected a number from 0 to 180, got '180.0001'"},
           {"infer " + cube + " -o " + out + " --crease-angle 0x10",
            "--crease-angle: expected a number from 0 to 180, got '0x10'"},
           {"info " + cube + " --weld ''", "--weld: expected a number >= 0, got ''"},
           {"info " + cube + " --weld nan", "--weld: expected a number >= 0, got 'nan'"},
           {"simplify " + cube + " -o " + out + " --ratio nan",
            "--ratio: expected a number > 0 and at most 1, got 'nan'"},
           {"simplify " + cube + " -o " + out + " --vertices abc",
            "--vertices: expected an integer from 4 to 1099511627776, got 'abc'"},
           {"simplify " + cube + " -o " + out + " --vertices 0x10",
            "--vertices: expected an integer from 4 to 1099511627776, got '0x10'"},
           {"subdivide " + cube + " -o " + out + " --levels 1.9",
            "--levels: expected an integer from 0 to 8, got '1.9'"},
           {"subdivide " + cube + " -o " + out + " --levels 4294967297",
            "--levels: expected an integer from 0 to 8, got '4294967297'"},
           {"tessellate " + cube + " -o " + out + " --level 1e18",
            "--level: expected an integer from 1 to 64, got '1e18'"}}) {
    const auto r = run_command(gpsurf(args));
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_EQ(r.output, "gpsurf: " + message + "\n") << args;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
  // 010 is ten levels, not eight (CLI11 alone reads it as octal): refused as more than 8.
  EXPECT_EQ(run_command(gpsurf("subdivide " + cube + " -o " + out + " --levels 010")).exit_code, 2);
  const auto two = run_command(gpsurf("subdivide " + cube + " -o " + out + " --levels +02"));
  EXPECT_EQ(two.exit_code, 0) << two.output;
}

TEST(Cli, RuntimeErrorsExitWithOneAndKeepFiles) {
  test::TempDir dir;
  const std::string bad =
      dir.write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nend_header\n1\n");
  const std::string keep = dir.write("keep.ply", "precious");
  for (const std::string& args :
       std::vector<std::string>{"info " + dir.file("missing.ply"), "info " + bad, "info " + dir.path().string(),
                                "subdivide " + bad + " -o " + keep, "subdivide " + dir.file("cube.ply") + " -o " + keep,
                                "sample cube -o " + dir.file("no/folder/c.ply")}) {
    const auto r = run_command(gpsurf(args));
    EXPECT_EQ(r.exit_code, 1) << args << ": " << r.output;
    EXPECT_EQ(test::line_count(r.output), 1u) << args << ": " << r.output;
    EXPECT_EQ(r.output.rfind("gpsurf: ", 0), 0u) << r.output;
  }
  std::ifstream in(keep);
  std::string contents((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(contents, "precious");
  // Loop on a quad mesh is refused with a message naming the face.
  run_command(gpsurf("sample cube -o " + dir.file("cube.ply")));
  const auto loop = run_command(gpsurf("subdivide " + dir.file("cube.ply") + " -o " + keep + " --scheme loop"));
  EXPECT_EQ(loop.exit_code, 1);
  EXPECT_NE(loop.output.find("face 0 has 4 vertices"), std::string::npos) << loop.output;
}

TEST(Cli, InferAndInfoOnPlainMeshes) {
  test::TempDir dir;
  // Two quads, the second with all corners at one point: inference (Eq. 16) refuses it, isotropic does not.
  const std::string obj = dir.write("strip.obj",
                                    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 5 5 5\nv 5 5 5\nv 5 5 5\nv 5 5 5\n"
                                    "f 1 2 3 4\nf 5 6 7 8\n");
  const auto inferred = run_command(gpsurf("infer " + obj + " -o " + dir.file("i.ply")));
  EXPECT_EQ(inferred.exit_code, 1) << inferred.output;
  EXPECT_NE(inferred.output.find("strip.obj: face 2 (line 10) is degenerate"), std::string::npos) << inferred.output;
  EXPECT_NE(inferred.output.find(obj), std::string::npos) << inferred.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("i.ply")));
  const auto isotropic = run_command(gpsurf("infer " + obj + " -o " + dir.file("j.ply") + " --isotropic 0.5"));
  EXPECT_EQ(isotropic.exit_code, 0) << isotropic.output;
  const auto both = run_command(gpsurf("infer " + obj + " -o " + dir.file("k.ply") + " --isotropic 0.5 --bias 0.1"));
  EXPECT_EQ(both.exit_code, 2) << both.output;
  // info on the isotropic result: σ = 0.5 × edge length 1 on the first quad gives eigenvalue 0.25.
  const auto info = run_command(gpsurf("info " + dir.file("j.ply")));
  EXPECT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("faces: 2 (2 with 4 sides)"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("boundary edges: 8"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("covariance eigenvalues: "), std::string::npos) << info.output;
}

// Saves onto what is not a regular file, or onto a read-only file, are refused at once (a FIFO with
// no reader would otherwise be replaced, or block); a hard-linked file keeps its links.
TEST(Cli, SavesOntoSpecialOrReadOnlyTargetsAreRefused) {
  test::TempDir dir;
  ASSERT_EQ(::mkfifo(dir.file("pipe.ply").c_str(), 0644), 0);
  const std::string read_only = dir.write("read-only.ply", "precious");
  std::filesystem::permissions(read_only, std::filesystem::perms::owner_read);
  for (const std::string& target : {dir.file("pipe.ply"), read_only}) {
    const auto r = run_command(gpsurf("sample cube -o " + target));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_EQ(test::line_count(r.output), 1u) << r.output;
    EXPECT_NE(r.output.find(target), std::string::npos) << r.output;
  }
  EXPECT_TRUE(std::filesystem::is_fifo(dir.file("pipe.ply")));
  std::ifstream in(read_only);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()), "precious");
  const std::string linked = dir.write("linked.ply", "old");
  std::filesystem::create_hard_link(linked, dir.file("second-name.ply"));
  EXPECT_EQ(run_command(gpsurf("sample cube -o " + linked)).exit_code, 0);
  EXPECT_EQ(std::filesystem::hard_link_count(linked), 2u);
  EXPECT_EQ(read_mesh(dir.file("second-name.ply")).n_vertices(), 8u);
}

// Bytes from a file and control bytes in a path reach the terminal escaped, on one line.
TEST(Cli, MessagesAreOneLineWithoutTheFilesControlBytes) {
  test::TempDir dir;
  const std::string obj = dir.write("evil\nname.obj", "v 0 \x1b]0;owned\x07" + std::string(100000, '9') + " 0\n");
  const auto r = run_command(gpsurf("info '" + obj + "'"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(test::line_count(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find("evil\\x0Aname.obj: line 1: '\\x1B]0;owned\\x07999"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  EXPECT_LT(r.output.size(), 400u) << r.output;
}

// Gaussians without faces have no surface: every command refuses them instead of writing an empty
// result with exit 0.
TEST(Cli, ACovarianceMeshWithoutFacesIsRefused) {
  test::TempDir dir;
  const std::string points = dir.write(
      "points.ply",
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\nproperty double z\n"
      "property double cxx\nproperty double cxy\nproperty double cxz\nproperty double cyy\nproperty double cyz\n"
      "property double czz\nend_header\n0 0 0 1 0 0 1 0 1\n");
  for (const std::string& args : {"info " + points, "tessellate " + points + " -o " + dir.file("t.ply"),
                                  "subdivide " + points + " -o " + dir.file("s.ply")}) {
    const auto r = run_command(gpsurf(args));
    EXPECT_EQ(r.exit_code, 1) << args << ": " << r.output;
    EXPECT_EQ(r.output, "gpsurf: " + points + ": the mesh has no faces\n") << args;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("t.ply")));
}

// A word the command line does not know is named in our words before anything else is checked: a
// command that is not one, an option before any command, an option the command does not have (not
// "file is required"), and an option given twice. A value that looks like an option (a negative
// number after an option that takes one) is still the option's value.
// Work on a mesh read from OBJ names its faces as the file does: from 1, with the line.
TEST(Cli, ALoopSubdivisionOfQuadsNamesTheFaceAsTheFileNumbersIt) {
  test::TempDir dir;
  const std::string obj = dir.write("quad.obj", "# a quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const auto r = run_command(gpsurf("subdivide " + obj + " -o " + dir.file("x.ply") + " --scheme loop"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.output,
            "gpsurf: " + obj + ": Loop subdivision needs a triangle mesh, but face 1 (line 6) has 4 vertices\n");
}

TEST(Cli, UnknownWordsAreNamedFirst) {
  test::TempDir dir;
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"bogus", "gpsurf: 'bogus' is not a command of gpsurf (gpsurf --help lists them)"},
           {"-x", "gpsurf: unknown option '-x' (a command comes first: gpsurf --help lists them)"},
           {"info --bogus", "gpsurf: unknown option '--bogus' (gpsurf info --help lists them)"},
           {"sample cube -o " + dir.file("c.ply") + " --size 5 --size 6",
            "gpsurf: --size is given 2 times; give it once"},
           {"sample cube -o " + dir.file("c.ply") + " --size -5", "gpsurf: --size: "},
           // CLI11's own wording ("--level: 1 required INT:INTEGER:[1, 64] missing", "The following
           // argument was not expected: b", "--level excludes --pixels", "foo not in {…}", "file is
           // required") in ours.
           {"tessellate " + dir.file("c.ply") + " -o " + dir.file("t.ply") + " --level",
            "gpsurf: --level needs a value after it"},
           {"info a.ply b.ply c.ply", "gpsurf: more words than the command takes: 'b.ply', 'c.ply'"},
           {"render a.ply -o a.png --level 4 --pixels 5",
            "gpsurf: --level and --pixels exclude each other; give one of them"},
           {"tessellate a.ply -o t.ply --scheme foo",
            "gpsurf: --scheme: expected one of auto, loop, catmull-clark, got 'foo'"},
           {"info", "gpsurf: the file is missing (the command's --help says what to give)"}}) {
    const auto r = run_command(gpsurf(args));
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_EQ(r.output.rfind(message, 0), 0u) << args << ": " << r.output;
    EXPECT_EQ(test::line_count(r.output), 1u) << r.output;
  }
}

// bench --model times the operations --operations names (by their first words) and no other; a word
// that names none, or --operations without --model, is a usage error naming it, before anything runs.
TEST(Cli, BenchModelTimesTheOperationsNamed) {
  test::TempDir dir;
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"bench --model --operations extrude,twirl",
            "gpsurf: bench --model: --operations: 'twirl' names no operation"},
           {"bench --model --operations loop,cut", "gpsurf: bench --model: --operations: 'cut' names no operation"},
           {"bench --edit --operations extrude", "gpsurf: bench: --operations goes with --model"}}) {
    const auto r = run_command(gpsurf(args));
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_EQ(r.output.rfind(message, 0), 0u) << args << ": " << r.output;
    EXPECT_EQ(test::line_count(r.output), 1u) << r.output;
  }
  const std::string json = dir.file("model.json");
  const auto r = run_command(gpsurf("bench --model --size 600 --operations 'loop cut',extrude --json " + json));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(json);
  std::stringstream text;
  text << in.rdbuf();
  const std::string figures = text.str();
  // The two named, in the bench's order, and no other row.
  const size_t extrude = figures.find("\"operation\": \"extrude 1 face\""),
               loop_cut = figures.find("\"operation\": \"loop cut\"");
  EXPECT_NE(extrude, std::string::npos) << figures;
  EXPECT_NE(loop_cut, std::string::npos) << figures;
  EXPECT_LT(extrude, loop_cut) << figures;
  size_t rows = 0;
  for (size_t at = figures.find("\"operation\":"); at != std::string::npos; at = figures.find("\"operation\":", at + 1))
    ++rows;
  EXPECT_EQ(rows, 2u) << figures;
}

}  // namespace
}  // namespace gps
