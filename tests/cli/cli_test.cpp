// `lancer` as users run it: the exit code, the one-line message, and never a partial PNG.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "image/image.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

std::string out_path(const std::string& name) {
    std::string path = test::output_dir() + "/cli-" + name + ".png";
    fs::remove(path);
    return path;
}

std::string bad(const std::string& name) { return test::source_path("tests/data/bad/" + name + ".toml"); }

const std::string kSmall = " --width 32 --height 18 --samples 1 ";

TEST(Cli, RendersTheSeedSceneWithAFinalTimingLine) {
    std::string out = out_path("seed");
    auto r = test::run_lancer("render " + test::source_path("scenes/seed.toml") + kSmall + "-o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Rgb8Image img = read_png(out);
    EXPECT_EQ(img.width, 32);
    EXPECT_EQ(img.height, 18);
    EXPECT_NE(r.err.find("Mrays/s"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
}

// Before a render's own progress, what takes time is shown on a terminal, each phase on the
// live line with its seconds, then cleared (LANCER_PHASE_AFTER_MS=0 draws each at once, where
// a user sees it after a second); off a terminal, nothing of it. `script` gives lancer a pty.
TEST(Cli, ATerminalSeesTheLoadAndTheBuildBeforeTheRender) {
    const std::string out = out_path("phases"), log = out + ".typescript";
    const std::string scene = test::source_path("scenes/seed.toml");
    const std::string inner = "LANCER_PHASE_AFTER_MS=0 " + std::string(LANCER_EXE) + " render " + scene + kSmall + "-o " + out;
    ASSERT_EQ(std::system(("script -qefc '" + inner + "' /dev/null >" + log + " 2>&1 </dev/null").c_str()), 0);
    const std::string tty = test::read_file(log);
    const auto reading = tty.find("\r\033[Kreading " + scene + "  0 s"), preparing = tty.find("\r\033[Kpreparing " + out);
    EXPECT_NE(reading, std::string::npos) << tty;
    EXPECT_NE(preparing, std::string::npos) << tty;
    EXPECT_LT(reading, preparing) << tty;
    EXPECT_LT(preparing, tty.find("Mrays/s")) << tty;
    const auto plain = test::run_lancer("render " + scene + kSmall + "-o " + out, "LANCER_PHASE_AFTER_MS=0");
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_EQ(plain.err.find("reading"), std::string::npos) << plain.err;
    EXPECT_EQ(plain.err.find('\r'), std::string::npos) << plain.err;
}

// As a packager installs it: `cmake --install build --prefix P` gives P/bin/lancer and the
// scenes in P/share/lancer/scenes; run from another directory, far from the source tree, it
// renders an installed scene (its patch file found beside it) to the same bytes as build/lancer.
TEST(Cli, TheInstalledLancerRendersFromAnyDirectory) {
    const std::string prefix = test::fresh_dir("cli-install");
    const std::string log = prefix + ".log";
    ASSERT_EQ(std::system(("cmake --install " + std::string(LANCER_BUILD_DIR) + " --prefix " + prefix + " >" + log + " 2>&1").c_str()), 0)
        << test::read_file(log);
    ASSERT_TRUE(test::file_exists(prefix + "/bin/lancer"));
    ASSERT_TRUE(test::file_exists(prefix + "/share/doc/lancer/README.md"));
    for (const char* name : {"seed", "teapot"}) {
        const std::string scene = prefix + "/share/lancer/scenes/" + name + ".toml";
        ASSERT_TRUE(test::file_exists(scene)) << scene;
        const std::string installed = prefix + "/" + name + "-installed.png", built = out_path(std::string(name) + "-built");
        const std::string run = "cd / && LANCER_VALIDATION=1 " + prefix + "/bin/lancer render " + scene + kSmall + "-o " + installed +
                                " >" + log + " 2>&1 </dev/null";
        ASSERT_EQ(std::system(run.c_str()), 0) << test::read_file(log);
        auto r = test::run_lancer("render " + test::source_path(std::string("scenes/") + name + ".toml") + kSmall + "-o " + built);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(read_png(installed).bytes, read_png(built).bytes) << name;
    }
}

// Any name the file system accepts works: the temporary file beside it (".NAME.XXXXXX") is
// shortened to fit. A name it does not accept is refused before anything is rendered.
TEST(Cli, OutputNamesUpToTheFileSystemsLimit) {
    std::string dir = test::fresh_dir("cli-long-names");
    std::string name = std::string(250, 'n') + ".png";  // 254 bytes
    auto r = test::run_lancer("render " + test::source_path("scenes/seed.toml") + kSmall + "-o " + dir + "/" + name);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_png(dir + "/" + name).width, 32);
    std::string too_long = std::string(252, 'n') + ".png";  // 256 bytes
    auto refused = test::run_lancer("render " + test::source_path("scenes/seed.toml") + kSmall + "-o " + dir + "/" + too_long);
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_NE(refused.err.find("its name is 256 bytes long, and the file system allows 255"), std::string::npos)
        << refused.err;
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1)
        << "the one image, and no temporary file";
}

TEST(Cli, CpuBackendAndOverridesWork) {
    std::string out = out_path("cpu");
    auto r = test::run_lancer("render " + test::source_path("scenes/phong.toml") +
                              " --backend cpu --width 20 --height 10 --samples 2 --max-depth 1 -q -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");  // --quiet
    EXPECT_EQ(read_png(out).width, 20);
}

// --samples and --max-depth give exactly the picture of a scene file whose [render] table says
// the same, and differ from the file's own values (seed.toml: 3 samples, 5 bounces, mirrors).
TEST(Cli, SamplesAndMaxDepthOverrideTheRenderTable) {
    std::string seed = test::read_file(test::source_path("scenes/seed.toml"));
    auto replace = [&](const std::string& from, const std::string& to) {
        ASSERT_NE(seed.find(from), std::string::npos) << from;
        seed.replace(seed.find(from), from.size(), to);
    };
    replace("samples = 3", "samples = 2");
    replace("max_depth = 5", "max_depth = 1");
    std::string edited = test::output_dir() + "/cli-seed-2-1.toml";
    test::write_file(edited, seed);
    const std::string size = " --width 48 --height 27 -q -o ";
    std::string by_file = out_path("by-file"), by_options = out_path("by-options"), plain = out_path("plain");
    ASSERT_EQ(test::run_lancer("render " + edited + size + by_file).exit_code, 0);
    auto r = test::run_lancer("render " + test::source_path("scenes/seed.toml") + " --samples 2 --max-depth 1" + size +
                              by_options);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_EQ(test::run_lancer("render " + test::source_path("scenes/seed.toml") + size + plain).exit_code, 0);
    EXPECT_EQ(read_png(by_options).bytes, read_png(by_file).bytes);
    EXPECT_NE(read_png(by_options).bytes, read_png(plain).bytes);
    // The final line states the rays per pixel the options asked for.
    auto line = test::run_lancer("render " + test::source_path("scenes/seed.toml") + " --samples 2 --width 8 --height 8 -o " +
                                 out_path("line"));
    EXPECT_NE(line.err.find("4 rays/pixel"), std::string::npos) << line.err;
}

// --aa-threshold is [render] aa_threshold; the final line reports the camera rays it traced and
// the share of pixels refined (seed at 48x27: sky, checker edges and silhouettes).
TEST(Cli, AaThresholdOptionIsTheRenderKeyAndReportsItsRays) {
    std::string seed = test::read_file(test::source_path("scenes/seed.toml"));
    const std::string from = "samples = 3";
    ASSERT_NE(seed.find(from), std::string::npos);
    seed.replace(seed.find(from), from.size(), "samples = 3\naa_threshold = 0.3");
    std::string edited = test::output_dir() + "/cli-seed-adaptive.toml";
    test::write_file(edited, seed);
    const std::string size = " --width 48 --height 27 -o ";
    std::string by_file = out_path("aa-by-file"), by_option = out_path("aa-by-option"), full = out_path("aa-full");
    auto r = test::run_lancer("render " + edited + size + by_file);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto o = test::run_lancer("render " + test::source_path("scenes/seed.toml") + " --aa-threshold 0.3" + size + by_option);
    ASSERT_EQ(o.exit_code, 0) << o.err;
    ASSERT_EQ(test::run_lancer("render " + test::source_path("scenes/seed.toml") + size + full + " -q").exit_code, 0);
    EXPECT_EQ(read_png(by_option).bytes, read_png(by_file).bytes);
    EXPECT_NE(read_png(by_option).bytes, read_png(full).bytes);
    EXPECT_NE(o.err.find(" rays/pixel on average ("), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("% of pixels refined, up to 9)"), std::string::npos) << o.err;
    // T = 0 refines everything: the full grid's bytes, and 1 + 9 camera rays per pixel.
    std::string zero = out_path("aa-zero");
    auto z = test::run_lancer("render " + test::source_path("scenes/seed.toml") + " --aa-threshold 0" + size + zero);
    ASSERT_EQ(z.exit_code, 0) << z.err;
    EXPECT_EQ(read_png(zero).bytes, read_png(full).bytes);
    EXPECT_NE(z.err.find("10.00 rays/pixel on average (100.0% of pixels refined, up to 9)"), std::string::npos) << z.err;
    // In steps (1, 2 x 2, 3 x 3) by the spread too: the same bytes, 1 + 4 + 9 rays per pixel.
    std::string steps = out_path("aa-steps");
    auto d = test::run_lancer("render " + test::source_path("scenes/seed.toml") +
                              " --aa-threshold 0 --aa-depth 2 --aa-method spread" + size + steps);
    ASSERT_EQ(d.exit_code, 0) << d.err;
    EXPECT_EQ(read_png(steps).bytes, read_png(full).bytes);
    EXPECT_NE(d.err.find("14.00 rays/pixel on average (100.0% of pixels refined, up to 9)"), std::string::npos) << d.err;
}

// The settings of adaptive anti-aliasing that mean nothing, or cannot be met, are errors, after
// the command line's overrides of the scene's [render] too.
TEST(Cli, AdaptiveSettingsThatCannotRunAreErrors) {
    const std::string seed = test::source_path("scenes/seed.toml") + " --width 8 --height 8 -o " + out_path("aa-refused");
    const std::pair<const char*, const char*> cases[] = {
        {" --aa-depth 2", "aa_depth needs aa_threshold"},
        {" --aa-method spread", "aa_method needs aa_threshold"},
        {" --aa-threshold 0.3 --aa-depth 3", "aa_depth 3: samples 3 has grids for at most 2 refinements"},
        {" --aa-threshold 0.3 --aa-depth 2 --samples 2", "aa_depth 2: samples 2 has grids for at most 1 refinement,"},
        {" --aa-threshold 0.3 --aa-method spread", "aa_method = \"spread\" needs aa_depth of at least 2"},
    };
    for (const auto& [args, message] : cases) {
        auto r = test::run_lancer("render " + seed + args);
        EXPECT_EQ(r.exit_code, 2) << args;
        EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    }
}

TEST(Cli, HelpVersionAndDevices) {
    auto help = test::run_lancer("render --help");
    EXPECT_EQ(help.exit_code, 0);
    for (const char* option : {"--width", "--height", "--samples", "--max-depth", "--backend", "--device", "--quiet"})
        EXPECT_NE(help.out.find(option), std::string::npos) << option;
    for (const char* args : {"--version", "render --version"}) {
        auto version = test::run_lancer(args);
        EXPECT_EQ(version.exit_code, 0) << args;
        EXPECT_NE(version.out.find("lancer "), std::string::npos) << args;
    }
    for (const char* args : {"--list-devices", "render --list-devices"}) {
        auto devices = test::run_lancer(args);
        EXPECT_EQ(devices.exit_code, 0) << args << ": " << devices.err;
        EXPECT_NE(devices.out.find("0: "), std::string::npos) << args << ": " << devices.out;
    }
    auto no_scene = test::run_lancer("render -o x.png");
    EXPECT_EQ(no_scene.exit_code, 2);
    EXPECT_NE(no_scene.err.find("a scene file is required"), std::string::npos) << no_scene.err;
}

// The message is expected at the start of stderr, after the output path is substituted.
using BadCase = test::RejectedCommand;

// A directory whose name ends in .png, in the way of an output file.
std::string directory_named_png() {
    std::string dir = test::output_dir() + "/cli-a-directory.png";
    fs::create_directories(dir);
    return dir;
}

// A small PNG in the output directory, for diff's inputs.
std::string small_png(const std::string& name) {
    std::string path = test::output_dir() + "/cli-input-" + name + ".png";
    write_png(path, Rgb8Image{4, 2, std::vector<std::uint8_t>(24, 100)});
    return path;
}

const std::string kSeedSmall = test::source_path("scenes/seed.toml") + kSmall;
const std::string kPhotonScene = test::source_path("tests/data/photons/small.toml") + " --backend cpu";
const std::string kNotDecimal = "' is not a whole number: write it in decimal digits";
const std::string kExposure = "the exposure must be a finite number of stops in [-64, 64], not ";

class CliRejects : public testing::TestWithParam<BadCase> {};

TEST_P(CliRejects, WithExitCode2AndOneMessageAndNoOutput) {
    const BadCase& c = GetParam();
    test::expect_refused(c.args, c.env, c.message, out_path("bad-" + c.name));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliRejects,
    testing::Values(
        BadCase{"unknown_key", "render " + bad("unknown_key") + " -o OUT", "", bad("unknown_key") + ":5:1: error: [camera]: unknown key 'fvo'"},
        BadCase{"negative_radius", "render " + bad("negative_radius") + " -o OUT", "", bad("negative_radius") + ":8:10: error:"},
        BadCase{"not_toml", "render " + bad("not_toml") + " -o OUT", "", bad("not_toml") + ":2:6: error:"},
        BadCase{"texture_missing", "render " + bad("texture_missing") + " -o OUT", "",
                bad("texture_missing") + ":6:11: error: cannot read texture 'textures/missing.png': No such file or directory"},
        BadCase{"texture_not_an_image", "render " + bad("texture_not_an_image") + " --backend cpu -o OUT", "",
                bad("texture_not_an_image") + ":6:20: error: cannot read texture 'textures/not_an_image.png': not a PNG"},
        BadCase{"missing_file", "render /nonexistent/scene.toml -o OUT", "", "lancer: error: cannot read scene file '/nonexistent/scene.toml'"},
        BadCase{"scene_is_directory", "render " + test::source_path("scenes") + " -o OUT", "", "lancer: error: cannot read scene file '" + test::source_path("scenes") + "': it is a directory"},
        BadCase{"output_dir_missing", "render " + test::source_path("scenes/seed.toml") + kSmall + "-o /nonexistent-dir/x.png", "",
                "lancer: error: cannot write '/nonexistent-dir/x.png': directory '/nonexistent-dir' does not exist"},
        BadCase{"output_is_directory", "render " + test::source_path("scenes/seed.toml") + kSmall + "-o " + directory_named_png(), "",
                "lancer: error: cannot write '" + directory_named_png() + "': it is a directory"},
        // /proc accepts no new files even from root: the failure comes at the final write.
        BadCase{"output_unwritable", "render " + test::source_path("scenes/seed.toml") + kSmall + "--backend cpu -q -o /proc/lancer.png", "",
                "lancer: error: cannot write '/proc/lancer.png'"},
        BadCase{"output_not_png", "render " + test::source_path("scenes/seed.toml") + kSmall + "-o " + test::output_dir() + "/cli-x.jpg", "",
                "lancer: error: --output: '" + test::output_dir() +
                    "/cli-x.jpg': lancer writes PNG, OpenEXR and PFM images, so the name must end in .png, .exr or .pfm"},
        BadCase{"animation_frames_exr", "render " + test::source_path("tests/data/anim/small.toml") + " -o " +
                    test::output_dir() + "/cli-anim_%d.exr", "",
                "lancer: error: -o " + test::output_dir() + "/cli-anim_%d.exr: animation frames are PNG images (a still may be .exr or .pfm)"},
        BadCase{"passes_without_photons", "render " + test::source_path("scenes/seed.toml") + kSmall + "--passes 4 -o OUT", "",
                "lancer: error: --passes: the scene does not use photon mapping (add a [photons] table, or --photons N)"},
        BadCase{"pass_range_beyond", "render " + test::source_path("tests/data/photons/small.toml") + " --backend cpu --pass-range 4-9 -o OUT", "",
                "lancer: error: --pass-range 4-9: the render has passes 0-5"},
        BadCase{"pass_range_malformed", "render " + test::source_path("tests/data/photons/small.toml") + " --backend cpu --pass-range 4-2 -o OUT", "",
                "lancer: error: --pass-range 4-2: expected A-B or N (0-based pass numbers)"},
        BadCase{"photons_light_without_power", "render " + test::source_path("scenes/seed.toml") + kSmall + "--photons 100 -o OUT", "",
                test::source_path("scenes/seed.toml") + ":21:1: error: photon mapping shoots photons by power, and this light has none"},
        BadCase{"output_empty", "render " + test::source_path("scenes/seed.toml") + kSmall + "-o ''", "",
                "lancer: error: --output: the output file name is empty"},
        BadCase{"too_large", "render " + test::source_path("scenes/seed.toml") + " --width 16384 --height 16384 -o OUT", "",
                "lancer: error: 16384x16384 exceeds the limit of 67108864 pixels"},
        BadCase{"bad_option", "render " + test::source_path("scenes/seed.toml") + " --samples 0 -o OUT", "", "lancer: error: --samples: Value 0 not in range"},
        BadCase{"aa_threshold_negative", "render " + test::source_path("scenes/seed.toml") + " --aa-threshold -0.1 -o OUT", "",
                "lancer: error: --aa-threshold: must be in [0, 3], not -0.1"},
        BadCase{"aa_threshold_nan", "render " + test::source_path("scenes/seed.toml") + " --aa-threshold nan -o OUT", "",
                "lancer: error: --aa-threshold: "},
        BadCase{"unknown_backend", "render " + test::source_path("scenes/seed.toml") + " --backend gpgpu -o OUT", "", "lancer: error: --backend: gpgpu not in"},
        BadCase{"no_vulkan_device", "render " + test::source_path("scenes/seed.toml") + kSmall + "-o OUT",
                "VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json", "lancer: error: no Vulkan device found"},
        BadCase{"unknown_device", "render " + test::source_path("scenes/seed.toml") + kSmall + "--device nosuchgpu -o OUT", "",
                "lancer: error: no Vulkan device matches 'nosuchgpu'"},
        // The renderer starts while the scene loads (app/renderer_start.hpp); the scene's and the
        // output's errors still come first, as if it had not.
        BadCase{"scene_error_before_device", "render " + bad("unknown_key") + " --device nosuchgpu -o OUT", "",
                bad("unknown_key") + ":5:1: error: [camera]: unknown key 'fvo'"},
        BadCase{"output_error_before_device", "render " + test::source_path("scenes/seed.toml") + kSmall +
                    "--device nosuchgpu -o /nonexistent-dir/x.png", "",
                "lancer: error: cannot write '/nonexistent-dir/x.png': directory '/nonexistent-dir' does not exist"},
        // Hostile input, round 3 (issue 42): integers are decimal digits (CLI11 read "0x10" as 16
        // and "010" as 8, and said "not in range" of "1e3").
        BadCase{"width_hex", "render " + kSeedSmall + "--width 0x10 -o OUT", "", "lancer: error: --width: '0x10" + kNotDecimal},
        BadCase{"width_exponent", "render " + kSeedSmall + "--width 1e3 -o OUT", "", "lancer: error: --width: '1e3" + kNotDecimal},
        BadCase{"samples_plus", "render " + kSeedSmall + "--samples +2 -o OUT", "", "lancer: error: --samples: '+2" + kNotDecimal},
        BadCase{"photons_hex", "render " + kPhotonScene + " --photons 0x100 -o OUT", "", "lancer: error: --photons: '0x100" + kNotDecimal},
        BadCase{"threshold_hex", "diff " + small_png("a") + " " + small_png("b") + " --threshold 0x8", "",
                "lancer: error: --threshold: '0x8" + kNotDecimal},
        // --exposure: NaN passed CLI::Range (a black picture, exit 0), in render, watch and view.
        BadCase{"exposure_nan", "render " + kSeedSmall + "--exposure nan -o OUT", "", "lancer: error: --exposure: " + kExposure + "nan"},
        BadCase{"exposure_inf", "render " + kSeedSmall + "--exposure inf -o OUT", "", "lancer: error: --exposure: " + kExposure + "inf"},
        BadCase{"exposure_beyond", "render " + kSeedSmall + "--exposure -65 -o OUT", "", "lancer: error: --exposure: " + kExposure + "-65"},
        BadCase{"watch_exposure_nan", "watch " + kSeedSmall + "--exposure nan -o OUT", "", "lancer: error: --exposure: " + kExposure + "nan"},
        BadCase{"view_exposure_nan", "view " + kSeedSmall + "--exposure NaN -o OUT", "", "lancer: error: --exposure: " + kExposure + "NaN"},
        // An empty value was taken for no value: all passes, all frames, no picture.
        BadCase{"pass_range_empty", "render " + kPhotonScene + " --pass-range '' -o OUT", "",
                "lancer: error: --pass-range: empty: expected A-B or N (0-based pass numbers)"},
        BadCase{"pass_range_signed", "render " + kPhotonScene + " --pass-range +1-3 -o OUT", "",
                "lancer: error: --pass-range +1-3: expected A-B or N (0-based pass numbers)"},
        BadCase{"pass_range_spaces", "render " + kPhotonScene + " --pass-range '1- 3' -o OUT", "",
                "lancer: error: --pass-range 1- 3: expected A-B or N (0-based pass numbers)"},
        BadCase{"frames_empty", "render " + test::source_path("tests/data/anim/small.toml") + " --frames '' -o OUT", "",
                "lancer: error: --frames: empty: expected A-B or N, frame numbers from 0"},
        BadCase{"side_by_side_empty", "diff " + small_png("a") + " " + small_png("b") + " --side-by-side ''", "",
                "lancer: error: --side-by-side: the output file name is empty"},
        BadCase{"side_by_side_jpg", "diff " + small_png("a") + " " + small_png("b") + " --side-by-side " + test::output_dir() + "/cli-side.jpg", "",
                "lancer: error: --side-by-side: '" + test::output_dir() + "/cli-side.jpg': a PNG image is written, so the name must end in .png"},
        BadCase{"view_output_exr", "view " + kSeedSmall + "-o " + test::output_dir() + "/cli-view.exr", "",
                "lancer: error: -o " + test::output_dir() + "/cli-view.exr: p saves PNG images, so the name must end in .png"}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// Integers are read as decimal, leading zeros and all (CLI11 read "010" as octal 8).
TEST(Cli, IntegersAreDecimal) {
    std::string out = out_path("decimal");
    auto r = test::run_lancer("render " + test::source_path("scenes/seed.toml") + " --width 010 --height 08 --samples 01 -q -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Rgb8Image img = read_png(out);
    EXPECT_EQ(img.width, 10);
    EXPECT_EQ(img.height, 8);
}

// An output that is one of the command's inputs (the same file by any name) is refused before
// anything is written: a texture of the scene, the scene itself, a frame over a texture, an
// image diff compares.
TEST(Cli, AnOutputThatIsAnInputIsRefused) {
    std::string dir = test::fresh_dir("output-is-input");
    fs::create_directories(dir + "/textures");
    write_png(dir + "/textures/wood.png", Rgb8Image{2, 2, std::vector<std::uint8_t>(12, 200)});
    test::write_file(dir + "/scene.toml", "[render]\nwidth = 8\nheight = 8\nsamples = 1\n[camera]\neye = [0, 0, -5]\n"
                                          "look_at = [0, 0, 0]\n[material.ball]\ntexture = \"textures/wood.png\"\n"
                                          "[[object]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"ball\"\n"
                                          "[[light]]\nposition = [0, 5, -5]\n");
    const std::string texture = test::read_file(dir + "/textures/wood.png");
    auto fine = test::run_lancer("render " + dir + "/scene.toml --backend cpu -q -o " + dir + "/out.png");
    ASSERT_EQ(fine.exit_code, 0) << fine.err;
    for (const std::string& output : {dir + "/textures/wood.png", dir + "/textures/../textures/wood.png"}) {
        auto r = test::run_lancer("render " + dir + "/scene.toml --backend cpu -q -o " + output);
        EXPECT_EQ(r.exit_code, 2) << output;
        EXPECT_EQ(r.err.rfind("lancer: error: cannot write '" + output + "': it is ", 0), 0u) << r.err;
    }
    fs::create_symlink(dir + "/textures/wood.png", dir + "/alias.png");
    auto alias = test::run_lancer("render " + dir + "/scene.toml --backend cpu -q -o " + dir + "/alias.png");
    EXPECT_EQ(alias.exit_code, 2);
    EXPECT_NE(alias.err.find("it is the input"), std::string::npos) << alias.err;
    EXPECT_EQ(test::read_file(dir + "/textures/wood.png"), texture);

    std::string a = small_png("diff-input-a"), b = small_png("diff-input-b");
    const std::string before = test::read_file(a);
    for (const std::string& output : {a, b}) {
        auto r = test::run_lancer("diff " + a + " " + b + " --side-by-side " + output);
        EXPECT_EQ(r.exit_code, 2);
        EXPECT_EQ(r.err, "lancer: error: cannot write '" + output + "': it is an input of this command\n");
    }
    EXPECT_EQ(test::read_file(a), before);
}

TEST(CliDiff, ReportsTheMetricAndWritesTheSideBySide) {
    std::string a = test::output_dir() + "/diff-a.png", b = test::output_dir() + "/diff-b.png";
    std::string side = test::output_dir() + "/diff-side.png";
    Rgb8Image img{4, 2, std::vector<std::uint8_t>(24, 100)};
    write_png(a, img);
    img.bytes[0] = 200;  // one pixel off by 100
    write_png(b, img);
    auto r = test::run_lancer("diff " + a + " " + b + " --side-by-side " + side);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("12.500% of pixels off by more than 4/255, largest difference 100/255"), std::string::npos) << r.out;
    EXPECT_EQ(read_png(side).width, 12);
    auto same = test::run_lancer("diff " + a + " " + a);
    EXPECT_NE(same.out.find("PSNR inf dB"), std::string::npos) << same.out;
    write_png(b, Rgb8Image{3, 2, std::vector<std::uint8_t>(18, 0)});
    auto sizes = test::run_lancer("diff " + a + " " + b);
    EXPECT_EQ(sizes.exit_code, 2);
    EXPECT_NE(sizes.err.find("images differ in size"), std::string::npos) << sizes.err;
}

}  // namespace
}  // namespace lancer
