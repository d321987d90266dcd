// How every output is written (files/output_file.h, docs/reliability.md "Outputs"): a temporary
// beside the target renamed over it, links replaced and never written through, streams written
// into and never renamed over, sets of files committed all or nothing, temporaries (any number of
// them, files and folders) removed on signals, concurrent writers of one file all succeeding.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "files/output_file.h"
#include "files/temporary_file.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;
namespace fs = std::filesystem;
using Catch::Contains;

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void write_file(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

bool has_hidden(const fs::path& dir) {
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (e.path().filename().string().rfind('.', 0) == 0) return true;
    }
    return false;
}

mode_t kind(const fs::path& p) {
    struct stat st {};
    return ::lstat(p.c_str(), &st) == 0 ? st.st_mode & S_IFMT : 0;
}

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const OutputError& e) {
        return e.what();
    }
    return "(written)";
}

}  // namespace

TEST_CASE("outputs: a link is replaced, a stream written into, a folder, socket or device refused", "[outputs]") {
    const fs::path dir = temp_dir("outputs-places");
    write_file(dir / "victim.txt", "precious");
    fs::create_symlink(dir / "victim.txt", dir / "out.txt");
    write_output(dir / "out.txt", "new");
    CHECK(slurp(dir / "victim.txt") == "precious");
    CHECK(kind(dir / "out.txt") == S_IFREG);
    CHECK(slurp(dir / "out.txt") == "new");
    // A dangling link, and one to a folder: replaced as well.
    fs::create_symlink(dir / "nowhere", dir / "dangling.txt");
    fs::create_directories(dir / "folder");
    fs::create_symlink(dir / "folder", dir / "to-folder.txt");
    write_output(dir / "dangling.txt", "a");
    write_output(dir / "to-folder.txt", "b");
    CHECK_FALSE(fs::exists(dir / "nowhere"));
    CHECK(slurp(dir / "to-folder.txt") == "b");
    CHECK(fs::is_empty(dir / "folder"));

    CHECK_THAT(error_of([&] { write_output(dir / "folder", "x"); }), Contains("folder: is a folder"));
    REQUIRE(::mkfifo((dir / "pipe").c_str(), 0600) == 0);
    CHECK_THAT(error_of([&] { write_output(dir / "pipe", "x"); }),
               Contains("pipe: is a FIFO; this output is written as a file"));
    CHECK_THAT(error_of([&] { write_output(dir / "pipe", "x", Streams::Allowed); }),
               Contains("a FIFO no process reads"));
    const int reader = ::open((dir / "pipe").c_str(), O_RDONLY | O_NONBLOCK);
    REQUIRE(reader >= 0);
    write_output(dir / "pipe", "through the pipe", Streams::Allowed);
    char got[64] = {};
    CHECK(::read(reader, got, sizeof got) == 16);
    ::close(reader);
    CHECK(std::string(got) == "through the pipe");
    CHECK(kind(dir / "pipe") == S_IFIFO);
    write_output("/dev/null", "nothing", Streams::Allowed);
    CHECK(kind("/dev/null") == S_IFCHR);
    CHECK_THAT(error_of([&] { write_output("/dev/null", "x"); }), Contains("/dev/null: is a character device"));
    CHECK_THAT(error_of([&] { write_output("/dev/stdout", "x"); }),
               Contains("/dev/stdout: is a stream of this process"));
    const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    const std::string socket_path = (dir / "socket").string();
    REQUIRE(socket_path.size() < sizeof address.sun_path);
    std::copy(socket_path.begin(), socket_path.end(), address.sun_path);
    REQUIRE(::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
    CHECK_THAT(error_of([&] { write_output(dir / "socket", "x", Streams::Allowed); }), Contains("socket: is a socket"));
    ::close(s);
    CHECK_THAT(error_of([&] { write_output(dir / "missing/out.txt", "x"); }), Contains("no folder"));
    CHECK_FALSE(has_hidden(dir));
}

TEST_CASE("outputs: folders a command fills are never links, copies read only regular files", "[outputs]") {
    const fs::path dir = temp_dir("outputs-folders");
    fs::create_directories(dir / "elsewhere");
    fs::create_symlink(dir / "elsewhere", dir / "images");
    CHECK_THAT(error_of([&] { make_output_folder(dir / "images", FolderLink::Refused); }),
               Contains("images: is a symbolic link"));
    CHECK_NOTHROW(make_output_folder(dir / "images", FolderLink::Followed));
    make_output_folder(dir / "a/b/c", FolderLink::Refused);
    CHECK(fs::is_directory(dir / "a/b/c"));
    write_file(dir / "file", "x");
    CHECK_THAT(error_of([&] { make_output_folder(dir / "file", FolderLink::Followed); }),
               Contains("file: is not a folder"));
    REQUIRE(::mkfifo((dir / "pipe").c_str(), 0600) == 0);
    CHECK_THAT(error_of([&] { copy_to_output(dir / "pipe", dir / "copy"); }), Contains("is not a regular file"));
    write_file(dir / "source", std::string(3 << 20, 'q'));
    copy_to_output(dir / "source", dir / "copy");
    CHECK(slurp(dir / "copy") == slurp(dir / "source"));
    CHECK_FALSE(fs::exists(dir / "elsewhere/copy"));
}

TEST_CASE("outputs: an input is found by its entry or by where a link to it leads", "[outputs]") {
    const fs::path dir = temp_dir("outputs-inputs");
    fs::create_directories(dir / "sub");
    write_file(dir / "scene.gltf", "{}");
    fs::create_symlink(dir / "scene.gltf", dir / "link.gltf");
    InputFiles inputs;
    inputs.add(dir / "link.gltf");
    CHECK(inputs.contains(dir / "sub/../scene.gltf"));  // where the link leads
    CHECK(inputs.contains(dir / "link.gltf"));          // the link itself
    CHECK_FALSE(inputs.contains(dir / "sub/scene.gltf"));
    InputFiles direct;
    direct.add(dir / "scene.gltf");
    CHECK_FALSE(direct.contains(dir / "link.gltf"));  // replacing that link leaves the scene untouched
}

TEST_CASE("outputs: writers of one file at once all succeed, each leaving it whole", "[outputs][concurrency]") {
    const fs::path dir = temp_dir("outputs-concurrent");
    std::vector<std::string> texts;
    for (char c : {'a', 'b', 'c', 'd'}) texts.push_back(std::string(1 << 16, c));
    std::vector<std::thread> writers;
    std::atomic<int> failures{0};
    for (const std::string& text : texts) {
        writers.emplace_back([&, text] {
            for (int i = 0; i < 50; ++i) {
                try {
                    write_output(dir / "report.xml", text, Streams::Allowed);
                } catch (const OutputError&) {
                    ++failures;
                }
            }
        });
    }
    for (std::thread& t : writers) t.join();
    CHECK(failures == 0);
    const std::string last = slurp(dir / "report.xml");
    CHECK(std::find(texts.begin(), texts.end(), last) != texts.end());
    CHECK_FALSE(has_hidden(dir));
}

TEST_CASE("outputs: a set of files is committed all or nothing, its errors naming the target", "[outputs]") {
    const fs::path dir = temp_dir("outputs-set");
    write_file(dir / "out.gltf", "old gltf");
    write_file(dir / "out.bin", "old bin");
    write_file(dir / "out-color.png", "old color");
    {
        OutputSet set(dir / "out.gltf");
        for (const char* name : {"out.bin", "out-color.png", "out-normal.png"})
            write_file(set.staged(name), std::string("new ") + name);
        // The staged scene vanishes before its rename: the last rename fails.
        const std::string error = error_of([&] { set.commit("out.gltf"); });
        CHECK_THAT(error, Contains((dir / "out.gltf").string() + ": cannot move the finished file into place") &&
                              Contains("every file of the set is as it was"));
        CHECK_THAT(error, !Contains(".out.gltf."));  // not the staging folder's path
    }
    CHECK(slurp(dir / "out.gltf") == "old gltf");
    CHECK(slurp(dir / "out.bin") == "old bin");
    CHECK(slurp(dir / "out-color.png") == "old color");
    CHECK_FALSE(fs::exists(dir / "out-normal.png"));
    CHECK_FALSE(has_hidden(dir));
    {
        OutputSet set(dir / "out.gltf");
        for (const char* name : {"out.bin", "out-color.png", "out.gltf"})
            write_file(set.staged(name), std::string("new ") + name);
        set.commit("out.gltf");
    }
    CHECK(slurp(dir / "out.gltf") == "new out.gltf");
    CHECK(slurp(dir / "out-color.png") == "new out-color.png");
    CHECK_FALSE(has_hidden(dir));
    // A folder where a file of the set goes: refused before anything moves, the folder kept.
    fs::create_directories(dir / "out-normal.png");
    write_file(dir / "out-normal.png/keep.txt", "kept");
    {
        OutputSet set(dir / "out.gltf");
        for (const char* name : {"out-normal.png", "out.gltf"}) write_file(set.staged(name), "newer");
        CHECK_THAT(error_of([&] { set.commit("out.gltf"); }), Contains("out-normal.png: is not a file"));
    }
    CHECK(slurp(dir / "out-normal.png/keep.txt") == "kept");
    CHECK(slurp(dir / "out.gltf") == "new out.gltf");
    CHECK_FALSE(has_hidden(dir));
    CHECK_THAT(error_of([&] { OutputSet set(dir / "missing/out.gltf"); }), Contains("missing/out.gltf: no folder"));
}

TEST_CASE("outputs: on SIGINT every temporary goes, however many (files, staging and scratch folders)",
          "[outputs][signals]") {
    for (const int sig : {SIGINT, SIGTERM}) {
        INFO("signal " << sig);
        const fs::path dir = temp_dir("outputs-signal-" + std::to_string(sig));
        const pid_t pid = ::fork();
        REQUIRE(pid >= 0);
        if (pid == 0) {
            remove_temporaries_on_signals();
            // More than any fixed table would hold, from several threads.
            std::vector<std::unique_ptr<TemporaryFile>> files;
            std::mutex lock;
            std::vector<std::thread> threads;
            for (int t = 0; t < 4; ++t) {
                threads.emplace_back([&] {
                    for (int i = 0; i < 20; ++i) {
                        auto f = std::make_unique<TemporaryFile>(dir / "frame.png");
                        const std::lock_guard guard(lock);
                        files.push_back(std::move(f));
                    }
                });
            }
            for (std::thread& t : threads) t.join();
            OutputSet set(dir / "out.gltf");
            write_file(set.staged("out-color.png"), "staged");
            ScratchFolder scratch(dir / "reference");
            write_file(scratch.path() / "reference-0.exr", "scratch");
            ::kill(::getpid(), sig);
            ::pause();
            ::_exit(0);
        }
        int status = 0;
        ::waitpid(pid, &status, 0);
        CHECK(WIFSIGNALED(status));
        CHECK(WTERMSIG(status) == sig);
        CHECK(fs::is_empty(dir));
    }
}

}  // namespace qs
