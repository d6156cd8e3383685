// legofeup_golden_tests: the golden-trace tests; with --print-pinned-text it prints the
// pinned file's text for this build instead (scripts/renew-golden.sh writes it).

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "golden_trace.hpp"

int main(int argc, char** argv) {
    if (argc == 2 && std::strcmp(argv[1], "--print-pinned-text") == 0) {
        using namespace legofeup::lessons::golden_testing;
        std::fputs(to_pinned_text(golden_run_fingerprint()).c_str(), stdout);
        return 0;
    }
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
