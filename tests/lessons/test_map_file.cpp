// Map files in the ROS map_server convention (docs/maps.md): hand-made YAML + PGM files in a
// temporary directory read into the cells worked out by hand here (thresholds, negate, the
// row flip, P5 8- and 16-bit and P2 with comments), and every malformed file is refused with
// its file, line and field.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "input_problems_test_support.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/map_file.hpp"
#include "scratch_dir_test_support.hpp"

namespace legofeup::lessons {
namespace {

using namespace scratch_testing;

std::string yaml_text(const std::string& image = "map.pgm", const std::string& extra = "") {
    return "image: " + image
           + "\n"                                  // line 1
             "resolution: 0.05\n"                  // line 2
             "origin: [-1.5, 2.25, 0.5]\n"         // line 3
             "occupied_thresh: 0.65\n"             // line 4
             "free_thresh: 0.196\n"                // line 5
             "negate: 0\n"                         // line 6
           + extra;
}

/// Writes map.yaml (with `yaml`) and map.pgm (with `image`) and loads them.
OccupancyGrid load(const std::string& yaml, const std::string& image) {
    const fs::path dir = temp_dir();
    write_file(dir / "map.yaml", yaml);
    write_file(dir / "map.pgm", image);
    return load_map_file(dir / "map.yaml");
}

std::string p5(int width, int height, const std::vector<int>& values, int maxval = 255) {
    std::string bytes = "P5\n" + std::to_string(width) + " " + std::to_string(height) + "\n"
                        + std::to_string(maxval) + "\n";
    for (const int value : values) {
        if (maxval > 255) {
            bytes += static_cast<char>(value >> 8);
        }
        bytes += static_cast<char>(value & 0xff);
    }
    return bytes;
}

template <class Action>
std::string map_error_of(Action action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no error)";
}

constexpr CellState F = CellState::Free;
constexpr CellState O = CellState::Occupied;
constexpr CellState U = CellState::Unknown;

// Rows of the grid from the bottom (grid row 0) up.
std::vector<std::vector<CellState>> rows_of(const OccupancyGrid& grid) {
    std::vector<std::vector<CellState>> rows;
    for (int row = 0; row < grid.height(); ++row) {
        std::vector<CellState> cells;
        for (int col = 0; col < grid.width(); ++col) {
            cells.push_back(grid.at({col, row}));
        }
        rows.push_back(cells);
    }
    return rows;
}

TEST(MapFile, ThresholdsDecideEachCellAsWorkedOutByHand) {
    // p = (255 − v)/255. Occupied when p > 0.65 ⇔ v < 89.25; free when p < 0.196 ⇔
    // v > 205.02; between them unknown. So 89 is occupied and 90 not; 205 is unknown
    // (p = 50/255 = 0.19608 ≥ 0.196) and 206 free.
    const OccupancyGrid grid = load(yaml_text(), p5(4, 2, {0, 89, 90, 205, 206, 254, 255, 128}));
    EXPECT_EQ(grid.width(), 4);
    EXPECT_EQ(grid.height(), 2);
    EXPECT_EQ(grid.resolution(), 0.05);
    EXPECT_EQ(grid.origin().x, -1.5);
    EXPECT_EQ(grid.origin().y, 2.25);
    EXPECT_EQ(grid.origin().theta, 0.5);
    // The image's first row (0, 89, 90, 205) is the top of the map: grid row 1.
    const std::vector<std::vector<CellState>> expected = {{F, F, F, U}, {O, O, U, U}};
    EXPECT_EQ(rows_of(grid), expected);
}

TEST(MapFile, TheImagesFirstRowIsTheTopOfTheMap) {
    // 2 wide, 3 high: only the top-left pixel is black.
    const OccupancyGrid grid = load(yaml_text(), p5(2, 3, {0, 254, 254, 254, 254, 254}));
    EXPECT_EQ(grid.at({0, 2}), O);
    EXPECT_EQ(grid.at({0, 0}), F);
    EXPECT_EQ(grid.at({1, 2}), F);
    int occupied = 0;
    for (const CellState state : grid.cells()) {
        occupied += state == O ? 1 : 0;
    }
    EXPECT_EQ(occupied, 1);
}

TEST(MapFile, NegateMakesWhiteOccupied) {
    // p = v/255: 255 → 1 (occupied), 0 → 0 (free), 100 → 0.39 (unknown).
    const OccupancyGrid grid = load(yaml_text() + "", p5(3, 1, {255, 0, 100}));
    EXPECT_EQ(rows_of(grid), (std::vector<std::vector<CellState>>{{F, O, U}}));
    std::string negated = yaml_text();
    negated.replace(negated.find("negate: 0"), 9, "negate: 1");
    const OccupancyGrid inverse = load(negated, p5(3, 1, {255, 0, 100}));
    EXPECT_EQ(rows_of(inverse), (std::vector<std::vector<CellState>>{{O, F, U}}));
}

TEST(MapFile, OwnThresholdsAndScaleModeAreRead) {
    // occupied_thresh 0.9: p > 0.9 ⇔ v < 25.5; free_thresh 0.1: p < 0.1 ⇔ v > 229.5.
    const std::string yaml =
        "image: map.pgm\nresolution: 0.1\norigin: [0, 0, 0]\noccupied_thresh: 0.9\n"
        "free_thresh: 0.1\nnegate: false\nmode: scale\n";
    const OccupancyGrid grid = load(yaml, p5(4, 1, {25, 26, 229, 230}));
    EXPECT_EQ(rows_of(grid), (std::vector<std::vector<CellState>>{{O, U, U, F}}));
}

TEST(MapFile, SixteenBitImagesUseTheirMaxval) {
    // maxval 1000: p = (1000 − v)/1000. 349 → 0.651 occupied, 350 → 0.65 not; 805 → 0.195
    // free, 804 → 0.196 not.
    const OccupancyGrid grid = load(yaml_text(), p5(4, 1, {349, 350, 804, 805}, 1000));
    EXPECT_EQ(rows_of(grid), (std::vector<std::vector<CellState>>{{O, U, U, F}}));
}

TEST(MapFile, PlainPgmWithCommentsReadsLikeTheBinaryOne) {
    const std::string plain =
        "P2\n# made by hand\n4 # width\n2\n# maxval next\n255\n"
        "0 89 90 205 # top row\n"
        "206 254\n255 128\n";
    const OccupancyGrid binary = load(yaml_text(), p5(4, 2, {0, 89, 90, 205, 206, 254, 255, 128}));
    const OccupancyGrid text = load(yaml_text(), plain);
    EXPECT_EQ(rows_of(text), rows_of(binary));
    // A comment right after the magic number, and Windows line ends.
    const OccupancyGrid crlf = load(yaml_text(), "P2 # plain\r\n2 1\r\n255\r\n0 254\r\n");
    EXPECT_EQ(rows_of(crlf), (std::vector<std::vector<CellState>>{{O, F}}));
}

TEST(MapFile, AnAbsoluteImagePathIsUsedAsItIs) {
    const fs::path dir = temp_dir();
    fs::create_directories(dir / "images");
    write_file(dir / "images" / "a.pgm", p5(1, 1, {0}));
    write_file(dir / "map.yaml", yaml_text((dir / "images" / "a.pgm").string()));
    EXPECT_EQ(load_map_file(dir / "map.yaml").at({0, 0}), O);
    // Relative to the YAML file, not to the working directory.
    write_file(dir / "rel.yaml", yaml_text("images/a.pgm"));
    EXPECT_EQ(load_map_file(dir / "rel.yaml").at({0, 0}), O);
}

// --- The YAML file's problems ---------------------------------------------------------------

/// The single problem of a map.yaml with `yaml` (and a valid 1×1 image).
InputProblem yaml_problem(const std::string& yaml) {
    const std::vector<InputProblem> problems =
        testing::input_problems_of([&] { load(yaml, p5(1, 1, {0})); });
    EXPECT_EQ(problems.size(), 1U);
    return problems.empty() ? InputProblem{} : problems.front();
}

/// `yaml_text()` with line `line` (1-based) replaced.
std::string with_line(int line, const std::string& text) {
    std::string yaml = yaml_text();
    std::size_t start = 0;
    for (int i = 1; i < line; ++i) {
        start = yaml.find('\n', start) + 1;
    }
    const std::size_t end = yaml.find('\n', start);
    return yaml.replace(start, end - start, text);
}

TEST(MapFile, BadResolutionIsReportedAtItsLine) {
    for (const std::string value : {"-0.05", "0", "11", ".inf", ".nan", "fine", "[1, 2]"}) {
        SCOPED_TRACE(value);
        const InputProblem problem = yaml_problem(with_line(2, "resolution: " + value));
        EXPECT_EQ(problem.line, 2);
        EXPECT_EQ(problem.key, "resolution");
        EXPECT_NE(problem.source.find("map.yaml"), std::string::npos);
    }
    const std::string message =
        map_error_of([] { load(with_line(2, "resolution: -0.05"), p5(1, 1, {0})); });
    EXPECT_NE(message.find("map.yaml:2: resolution = -0.05: must be greater than 0 and at most "
                           "10 m per pixel"),
              std::string::npos)
        << message;
    EXPECT_EQ(yaml_problem(with_line(2, "resolution: .inf")).reason, "must be a finite number");
}

TEST(MapFile, BadOriginIsReportedAtItsLine) {
    InputProblem problem = yaml_problem(with_line(3, "origin: [1.0, 2.0]"));
    EXPECT_EQ(problem.line, 3);
    EXPECT_EQ(problem.key, "origin");
    EXPECT_NE(problem.reason.find("[x, y, yaw]"), std::string::npos);
    problem = yaml_problem(with_line(3, "origin: [1.0, north, 0.0]"));
    EXPECT_EQ(problem.line, 3);
    EXPECT_EQ(problem.key, "origin y");
    EXPECT_EQ(problem.value, "north");
    problem = yaml_problem(with_line(3, "origin: [2e6, 0, 0]"));
    EXPECT_EQ(problem.key, "origin");
    EXPECT_NE(problem.reason.find("within ±1e+06 m"), std::string::npos) << problem.reason;
}

TEST(MapFile, ThresholdsOutsideZeroToOneOrOutOfOrderAreRefused) {
    InputProblem problem = yaml_problem(with_line(4, "occupied_thresh: 1.5"));
    EXPECT_EQ(problem.line, 4);
    EXPECT_EQ(problem.key, "occupied_thresh");
    EXPECT_EQ(problem.value, "1.5");
    problem = yaml_problem(with_line(5, "free_thresh: -0.1"));
    EXPECT_EQ(problem.line, 5);
    EXPECT_EQ(problem.key, "free_thresh");
    // free ≥ occupied: reported at free_thresh's line, naming both.
    problem = yaml_problem(with_line(5, "free_thresh: 0.7"));
    EXPECT_EQ(problem.line, 5);
    EXPECT_EQ(problem.key, "free_thresh");
    EXPECT_EQ(problem.message().substr(problem.message().find("map.yaml")),
              "map.yaml:5: free_thresh = 0.7: must be below occupied_thresh (0.65): between "
              "the two a cell is unknown");
    EXPECT_EQ(yaml_problem(with_line(5, "free_thresh: 0.65")).key, "free_thresh");
}

TEST(MapFile, NegateModeUnknownDuplicateAndMissingFieldsAreNamed) {
    InputProblem problem = yaml_problem(with_line(6, "negate: 2"));
    EXPECT_EQ(problem.line, 6);
    EXPECT_EQ(problem.key, "negate");
    problem = yaml_problem(yaml_text() + "mode: raw\n");
    EXPECT_EQ(problem.line, 7);
    EXPECT_EQ(problem.key, "mode");
    EXPECT_NE(problem.reason.find("not supported"), std::string::npos);
    problem = yaml_problem(yaml_text() + "mode: fancy\n");
    EXPECT_EQ(problem.reason, "must be trinary or scale");
    problem = yaml_problem(yaml_text() + "resolutoin: 0.1\n");
    EXPECT_EQ(problem.line, 7);
    EXPECT_EQ(problem.key, "resolutoin");
    EXPECT_NE(problem.reason.find("unknown field"), std::string::npos);
    problem = yaml_problem(yaml_text() + "resolution: 0.1\n");
    EXPECT_EQ(problem.line, 7);
    EXPECT_EQ(problem.reason, "written twice (first on line 2)");
    // A missing field has no line of its own.
    problem = yaml_problem(with_line(6, "# negate left out"));
    EXPECT_EQ(problem.line, 0);
    EXPECT_EQ(problem.key, "negate");
    EXPECT_NE(problem.reason.find("missing"), std::string::npos);
}

TEST(MapFile, EveryProblemOfAFileIsListedInLineOrder) {
    const std::vector<InputProblem> problems = testing::input_problems_of([] {
        load(
            "image: map.pgm\nresolution: -1\norigin: [0, 0]\noccupied_thresh: 2\n"
            "free_thresh: 0.1\nnegate: 0\n",
            p5(1, 1, {0}));
    });
    ASSERT_EQ(problems.size(), 3U);
    EXPECT_EQ(problems[0].line, 2);
    EXPECT_EQ(problems[1].line, 3);
    EXPECT_EQ(problems[2].line, 4);
}

TEST(MapFile, InvalidYamlAndNonMappingsAreRefusedWithTheirLine) {
    InputProblem problem = yaml_problem("image: map.pgm\nresolution: [0.05\n");
    EXPECT_GE(problem.line, 2);
    EXPECT_NE(problem.reason.find("not valid YAML"), std::string::npos);
    problem = yaml_problem("");
    EXPECT_NE(problem.reason.find("empty"), std::string::npos);
    problem = yaml_problem("- just\n- a list\n");
    EXPECT_NE(problem.reason.find("not a map file"), std::string::npos);
}

TEST(MapFile, AMissingImageIsReportedAtTheYamlsImageLine) {
    const fs::path dir = temp_dir();
    write_file(dir / "map.yaml", yaml_text("nowhere.pgm"));
    const std::vector<InputProblem> problems =
        testing::input_problems_of([&] { load_map_file(dir / "map.yaml"); });
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].source, (dir / "map.yaml").string());
    EXPECT_EQ(problems[0].line, 1);
    EXPECT_EQ(problems[0].key, "image");
    EXPECT_EQ(problems[0].value, "nowhere.pgm");
    EXPECT_NE(problems[0].reason.find((dir / "nowhere.pgm").string()), std::string::npos);
    // And a missing YAML file.
    EXPECT_NE(map_error_of([&] { load_map_file(dir / "absent.yaml"); }).find("cannot open"),
              std::string::npos);
}

// --- The PGM image's problems ---------------------------------------------------------------

/// The single problem of map.pgm with `image` (and a valid YAML file).
InputProblem image_problem(const std::string& image) {
    const std::vector<InputProblem> problems =
        testing::input_problems_of([&] { load(yaml_text(), image); });
    EXPECT_EQ(problems.size(), 1U);
    return problems.empty() ? InputProblem{} : problems.front();
}

TEST(MapFile, PgmHeaderProblemsNameTheHeaderAndItsLine) {
    InputProblem problem = image_problem("P6\n1 1\n255\nabc");
    EXPECT_EQ(problem.key, "PGM header");
    EXPECT_NE(problem.source.find("map.pgm"), std::string::npos);
    EXPECT_NE(problem.reason.find("Netpbm P6"), std::string::npos) << problem.reason;
    problem = image_problem("GIF89a");
    EXPECT_NE(problem.reason.find("not a PGM image"), std::string::npos);
    problem = image_problem("P5\n# comment\nwide 2\n255\n");
    EXPECT_EQ(problem.line, 3);
    EXPECT_EQ(problem.reason, "expected the width (a whole number), found \"wide\"");
    problem = image_problem("P5\n4097 1\n255\n");
    EXPECT_EQ(problem.line, 2);
    EXPECT_EQ(problem.reason,
              "the image is 4097×1 pixels, larger than a map image may be (at most 4096×4096)");
    problem = image_problem("P5\n1\n5000\n255\n");
    EXPECT_EQ(problem.line, 3);
    EXPECT_EQ(problem.reason,
              "the image is 1×5000 pixels, larger than a map image may be (at most 4096×4096)");
    problem = image_problem("P5\n4096 0\n255\n");
    EXPECT_EQ(problem.reason, "the height 0 must be at least 1");
    problem = image_problem("P5\n1 1\n0\n");
    EXPECT_EQ(problem.reason, "the maxval 0 must be between 1 and 65535");
    problem = image_problem("P5\n1 1\n");
    EXPECT_EQ(problem.reason, "expected the maxval (a whole number), found the end of the file");
    const std::string message = map_error_of([] { load(yaml_text(), "P5\n\n\nx 1\n255\n"); });
    EXPECT_NE(message.find("map.pgm:4: PGM header: expected the width"), std::string::npos)
        << message;
}

// A 20000 × 20000 image is 400 MB of pixels (800 MB as the reader's 16-bit buffer): its
// size must be refused from the header, before the pixels are counted, allocated or read.
TEST(MapFile, AnImageTooLargeIsRefusedFromItsHeaderAlone) {
    const std::string too_large =
        "the image is 20000×20000 pixels, larger than a map image may be (at most 4096×4096)";
    // No pixels at all: had they been counted first, this would be "expected 20000×20000 =
    // 400000000 pixels (8-bit), found 0".
    EXPECT_EQ(map_error_of([] { parse_pgm("P5\n20000 20000\n255\n", "big.pgm"); }),
              "big.pgm:2: PGM header: " + too_large);
    EXPECT_EQ(map_error_of([] { parse_pgm("P2\n# plain\n20000\n20000\n255\n", "big.pgm"); }),
              "big.pgm:4: PGM header: " + too_large);
    // Digits beyond any int are named as written.
    EXPECT_NE(map_error_of([] {
                  parse_pgm("P5 123456789012345 1 255\n", "x.pgm");
              }).find("the image is 123456789012345×1 pixels"),
              std::string::npos);

    // On disk, with all its 400 000 000 bytes of pixels (a sparse file: it takes no space).
    // Read whole it would be refused by its file size (above the 128 MiB a map image may
    // be) after reading it; read header first, its width × height are named.
    const fs::path dir = temp_dir();
    write_file(dir / "map.yaml", yaml_text());
    const std::string header = "P5\n20000 20000\n255\n";
    write_file(dir / "map.pgm", header);
    fs::resize_file(dir / "map.pgm", header.size() + 20000ULL * 20000ULL);
    const std::vector<InputProblem> problems =
        testing::input_problems_of([&] { load_map_file(dir / "map.yaml"); });
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].message(), (dir / "map.pgm").string() + ":2: PGM header: " + too_large);
    fs::remove(dir / "map.pgm");  // sparse, but it looks like 400 MB to anyone listing /tmp
}

// The header is read from the file's first 64 KiB; one that goes on beyond them is refused,
// even when what follows would complete it: a number cut by the window's end is not read
// as a shorter one.
TEST(MapFile, AFileHeaderMustEndWithinItsFirst64KiB) {
    constexpr std::size_t kWindow = 64 * 1024;
    const std::string too_long =
        "PGM header: does not end within the file's first 65536 bytes (a header is the magic "
        "number, width, height and maxval, with their comments)";
    // A comment longer than the window.
    const std::string long_comment = "P5\n#" + std::string(kWindow, 'c') + "\n1 1\n255\n";
    EXPECT_NE(map_error_of([&] {
                  load(yaml_text(), long_comment + std::string(1, '\0'));
              }).find("map.pgm:2: " + too_long),
              std::string::npos);
    // The maxval's digits "25" end the window and "5" follows: not read as 25.
    std::string cut = "P5\n1 1\n#";
    cut += std::string(kWindow - cut.size() - 3, 'c') + "\n25";
    ASSERT_EQ(cut.size(), kWindow);
    EXPECT_NE(map_error_of([&] {
                  load(yaml_text(), cut + "5\n" + std::string(1, '\x80'));
              }).find("map.pgm:4: " + too_long),
              std::string::npos);
    // Within the window, a header of long comments and an image beyond it read whole.
    std::string fits = "P5\n#" + std::string(kWindow - 100, 'c') + "\n300 300\n255\n";
    fits += std::string(300 * 300, '\0');
    const OccupancyGrid grid = load(yaml_text(), fits);
    EXPECT_EQ(grid.width(), 300);
    EXPECT_TRUE(grid.occupied({299, 299}));
}

TEST(MapFile, TooFewOrTooManyPixelsAreCounted) {
    InputProblem problem = image_problem(p5(3, 2, {0, 0, 0, 0, 0}).substr(0) + "");
    // p5() wrote 5 values for a 3×2 image.
    EXPECT_EQ(problem.line, 0);
    EXPECT_EQ(problem.reason, "expected 3×2 = 6 pixels (8-bit), found 5");
    problem = image_problem(p5(2, 1, {0, 0, 0}));
    EXPECT_EQ(problem.reason, "expected 2×1 = 2 pixels (8-bit), found 3");
    problem = image_problem(p5(2, 1, {0, 0}, 1000) + "x");
    EXPECT_EQ(problem.reason, "expected 2×1 = 2 pixels (16-bit), found 2 and a half");
    problem = image_problem("P2\n3 2\n255\n0 0 0\n0 0\n");
    EXPECT_EQ(problem.reason, "expected 3×2 = 6 pixels, found 5");
    const std::string message = map_error_of([] { load(yaml_text(), p5(1, 2, {0})); });
    EXPECT_NE(message.find("map.pgm: expected 1×2 = 2 pixels (8-bit), found 1"), std::string::npos)
        << message;
}

TEST(MapFile, PixelsAboveTheMaxvalOrNotNumbersAreNamed) {
    InputProblem problem = image_problem(p5(2, 1, {0, 201}, 200));
    EXPECT_EQ(problem.key, "pixel (column 1, row 0)");
    EXPECT_EQ(problem.value, "201");
    EXPECT_EQ(problem.reason, "above the maxval 200");
    problem = image_problem(p5(2, 2, {0, 0, 0, 1001}, 1000));
    EXPECT_EQ(problem.key, "pixel (column 1, row 1)");
    problem = image_problem("P2\n2 2\n100\n0 0\n\n0 300\n");
    EXPECT_EQ(problem.line, 6);
    EXPECT_EQ(problem.key, "pixel (column 1, row 1)");
    EXPECT_EQ(problem.value, "300");
    problem = image_problem("P2\n2 1\n255\n0 -4\n");
    EXPECT_EQ(problem.line, 4);
    EXPECT_EQ(problem.key, "pixel (column 1, row 0)");
    EXPECT_EQ(problem.value, "\"-4\"");
    EXPECT_EQ(problem.reason, "not a whole number");
}

TEST(MapFile, CellStateOfFollowsTheRosFormula) {
    // Independent of the image reader: every 8-bit value against the formula.
    MapMetadata map;
    for (int value = 0; value <= 255; ++value) {
        const double p = (255.0 - value) / 255.0;
        const CellState expected = p > 0.65 ? O : p < 0.196 ? F : U;
        EXPECT_EQ(cell_state_of(map, 255, value), expected) << value;
    }
    map.negate = true;
    EXPECT_EQ(cell_state_of(map, 255, 255), O);
    EXPECT_EQ(cell_state_of(map, 255, 0), F);
}

}  // namespace
}  // namespace legofeup::lessons
