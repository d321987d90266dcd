// The throughput bench's peer children: the report a child prints and its parser (a malformed
// report is an error, never a measurement), the width named by llvmpipe's renderer string, and
// running a child with an argument vector and an explicit environment.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "bench/child_process.h"
#include "bench/peer_report.h"

namespace qs::bench {

namespace {
const char* const kGood =
    "quadshade-peer-renderer llvmpipe (LLVM 15.0.6, 512 bits)\n"
    "quadshade-peer-timing median_ms=12.5 min_ms=12 max_ms=14.25 setup_ms=31\n";
}

TEST_CASE("peer report: what a child formats, the parent parses back exactly") {
    PeerReport r;
    r.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    r.median_ms = 1.0 / 3.0;
    r.min_ms = 0.1;
    r.max_ms = 7.0 / 3.0;
    r.setup_ms = 42.125;
    const PeerReport back = parse_peer_report(format_peer_report(r));
    CHECK(back.renderer == r.renderer);
    CHECK(back.median_ms == r.median_ms);  // shortest round-trip digits: bit for bit
    CHECK(back.min_ms == r.min_ms);
    CHECK(back.max_ms == r.max_ms);
    CHECK(back.setup_ms == r.setup_ms);
}

TEST_CASE("peer report: other lines are ignored, fields in any order, CRLF accepted") {
    const PeerReport r = parse_peer_report(
        "Mesa warning: something\r\n"
        "quadshade-peer-timing setup_ms=31 max_ms=14.25  min_ms=12 median_ms=12.5\r\n"
        "quadshade-peer-renderer llvmpipe (LLVM 15.0.6, 512 bits)\r\n");
    CHECK(r.renderer == "llvmpipe (LLVM 15.0.6, 512 bits)");
    CHECK(r.median_ms == 12.5);
    CHECK(r.min_ms == 12);
    CHECK(r.max_ms == 14.25);
    CHECK(r.setup_ms == 31);
    CHECK(parse_peer_report(kGood).median_ms == 12.5);
}

TEST_CASE("peer report: anything malformed is refused, saying what") {
    auto refused = [](const std::string& text, const std::string& why) {
        INFO(text);
        CHECK_THROWS_WITH(parse_peer_report(text), Catch::Contains(why));
    };
    const std::string renderer = "quadshade-peer-renderer llvmpipe (LLVM 15.0.6, 256 bits)\n";
    refused("", "no renderer line");
    refused(renderer, "no timing line");
    refused("quadshade-peer-timing median_ms=1 min_ms=1 max_ms=1 setup_ms=1\n", "no renderer line");
    refused("quadshade-peer-renderer \nquadshade-peer-timing median_ms=1 min_ms=1 max_ms=1 setup_ms=1\n",
            "no renderer line");
    refused(std::string(kGood) + kGood, "two renderer lines");
    refused(renderer + "quadshade-peer-timing median_ms=1 min_ms=1 max_ms=1\n", "no 'setup_ms'");
    refused(renderer + "quadshade-peer-timing median_ms=1 min_ms=1 max_ms=1 setup_ms=1 median_ms=1\n", "given twice");
    refused(renderer + "quadshade-peer-timing median_ms=1 min_ms=1 max_ms=1 setup_ms=1 mean_ms=1\n", "unknown field");
    refused(renderer + "quadshade-peer-timing median_ms=1 min_ms=1 max_ms=1 setup_ms\n", "not key=value");
    refused(renderer + "quadshade-peer-timing median_ms=1ms min_ms=1 max_ms=1 setup_ms=1\n", "not a number");
    refused(renderer + "quadshade-peer-timing median_ms= min_ms=1 max_ms=1 setup_ms=1\n", "not a number");
    refused(renderer + "quadshade-peer-timing median_ms=nan min_ms=1 max_ms=1 setup_ms=1\n", "not a finite time");
    refused(renderer + "quadshade-peer-timing median_ms=inf min_ms=1 max_ms=inf setup_ms=1\n", "not a finite time");
    refused(renderer + "quadshade-peer-timing median_ms=-1 min_ms=-2 max_ms=1 setup_ms=1\n", "not a finite time");
    refused(renderer + "quadshade-peer-timing median_ms=5 min_ms=6 max_ms=7 setup_ms=1\n", "min <= median <= max");
}

TEST_CASE("peer report: the vector width llvmpipe names in its renderer string") {
    CHECK(vector_bits_of("llvmpipe (LLVM 15.0.6, 256 bits)") == 256);
    CHECK(vector_bits_of("llvmpipe (LLVM 19.1.7, 512 bits)") == 512);
    CHECK(vector_bits_of("llvmpipe (LLVM 15.0.6, 128 bits)") == 128);
    CHECK_FALSE(vector_bits_of("softpipe"));
    CHECK_FALSE(vector_bits_of("llvmpipe (LLVM 15.0.6,  bits)"));
    CHECK_FALSE(vector_bits_of(""));
}

TEST_CASE("child process: exactly the environment given, stdout and stderr apart, exit status and signal") {
    const ChildOutput env = run_child({"/usr/bin/env"}, {"ONLY=this", "LP_NATIVE_VECTOR_WIDTH=512"});
    CHECK(env.ok());
    CHECK(env.out == "ONLY=this\nLP_NATIVE_VECTOR_WIDTH=512\n");
    CHECK(env.err.empty());

    // Arguments are passed as they are (no shell: the quotes and the $ stay).
    const ChildOutput args = run_child({"/bin/sh", "-c", "printf '%s|' \"$@\"; echo oops >&2; exit 3", "sh", "a b", "$HOME"}, {});
    CHECK(args.exit_code == 3);
    CHECK_FALSE(args.ok());
    CHECK(args.out == "a b|$HOME|");
    CHECK(args.err == "oops\n");
    CHECK(args.status() == "exit status 3");

    const ChildOutput killed = run_child({"/bin/sh", "-c", "kill -ABRT $$"}, {});
    CHECK_FALSE(killed.ok());
    CHECK(killed.signal == 6);
    CHECK(killed.status().find("killed by signal 6") == 0);

    // More than a pipe holds on both streams at once does not block either.
    const ChildOutput big = run_child({"/bin/sh", "-c", "head -c 300000 /dev/zero; head -c 300000 /dev/zero >&2"}, {});
    CHECK(big.ok());
    CHECK(big.out.size() == 300000);
    CHECK(big.err.size() == 300000);

    CHECK_THROWS_WITH(run_child({"/no/such/program"}, {}), Catch::Contains("cannot run /no/such/program"));
}

TEST_CASE("child process: the environment with some variables replaced") {
    ::setenv("QS_TEST_REPLACED", "old", 1);
    const std::vector<std::string> env = environment_with({"QS_TEST_REPLACED=new", "QS_TEST_ADDED=1"});
    int replaced = 0, added = 0;
    for (const std::string& e : env) {
        replaced += e.rfind("QS_TEST_REPLACED=", 0) == 0;
        added += e.rfind("QS_TEST_ADDED=", 0) == 0;
        CHECK(e != "QS_TEST_REPLACED=old");
    }
    CHECK(replaced == 1);
    CHECK(added == 1);
    ::unsetenv("QS_TEST_REPLACED");
}

}  // namespace qs::bench
