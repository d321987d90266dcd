// The mutation run: scenes made by breaking the shipped ones at random (a JSON value
// replaced by a hostile one, an array emptied, cut or multiplied, a key dropped, extras nested
// deep, the buffer's bytes changed or cut), each loaded and rendered by both backends in a child
// process under a time limit. Every scene must end in a frame or in a message (exit 0 or 1); a
// signal, a sanitizer report, a hang or another exit fails the run, and the scene is kept. A
// report is looked for in the child's error output whatever its exit status: UBSan and ASan end
// a process with status 1 unless told to abort, and 1 is also a refusal.
//
//   quadshade-mutation-run COUNT [SEED] [KEEP_DIR]
//
// Prints a table of outcomes and the most frequent messages. Deterministic for a seed.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "shading/catalogue.h"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const fs::path kAssets = fs::path(QUADSHADE_SOURCE_DIR) / "scenes/assets";

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Every value in a JSON document, by reference, for picking one at random.
void collect(json& node, std::vector<json*>& out) {
    out.push_back(&node);
    if (node.is_object() || node.is_array()) {
        for (json& child : node) collect(child, out);
    }
}

class Mutator {
public:
    explicit Mutator(unsigned seed) : rng_(seed) {}

    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

    void mutate(json& doc) {
        std::vector<json*> nodes;
        collect(doc, nodes);
        json& n = *nodes[std::size_t(pick(int(nodes.size())))];
        if (n.is_number()) {
            static const json kNumbers[] = {0, -1, 1, 2, 3, 5121, 5126, 2147483647, 2147483648ll, 4294967296ll,
                                            9007199254740993ll, 9223372036854775807ll, 18446744073709551615ull,
                                            -9223372036854775807ll, 1e38, 1e39, -1e39, 1e-45, 0.5, 1e308, 65536};
            n = kNumbers[pick(int(std::size(kNumbers)))];
        } else if (n.is_string()) {
            static const char* const kStrings[] = {"", "../table-1.1-plane.bin", "/etc/passwd", "http://example.com/a.bin",
                                                   "data:application/octet-stream;base64,AAAA", "%", "textures",
                                                   "textures/halftone-source.png", "/dev/zero", "VEC4", "SCALAR",
                                                   "orthographic", "perspective", "halftone", "file:///etc/passwd"};
            n = pick(8) == 0 ? json(std::string(10000, 'x')) : json(kStrings[pick(int(std::size(kStrings)))]);
        } else if (n.is_array() && !n.empty()) {
            switch (pick(4)) {
                case 0: n.erase(n.begin() + pick(int(n.size()))); break;
                case 1: n.push_back(n[std::size_t(pick(int(n.size())))]); break;
                case 2: n = json::array(); break;
                default: n.push_back(pick(100) - 10); break;
            }
        } else if (n.is_object() && !n.empty()) {
            if (pick(3) == 0) {
                json deep = 1;
                for (int i = pick(120); i > 0; --i) deep = json::array({deep});
                n["extras"] = deep;
            } else {
                auto it = n.begin();
                std::advance(it, pick(int(n.size())));
                n.erase(it);
            }
        } else {
            n = pick(2) ? json(-1) : json(nullptr);
        }
    }

    void mutate(std::string& bytes) {
        if (bytes.empty()) return;
        if (pick(4) == 0) {
            bytes.resize(std::size_t(pick(int(bytes.size()))));
            return;
        }
        for (int i = 1 + pick(16); i > 0 && !bytes.empty(); --i) {
            static const char kBytes[] = {0, '\x7f', '\x80', '\xff'};
            const std::size_t at = std::size_t(pick(int(bytes.size())));
            bytes[at] = pick(2) ? kBytes[pick(4)] : char(pick(256));
            if (pick(2)) bytes[at & ~std::size_t(3)] = '\xff';  // a float's exponent: huge, Inf or NaN
        }
    }

private:
    std::mt19937 rng_;
};

// A shader each render uses, from those this build has: texture, derivatives, window coordinates.
std::vector<std::string> shaders() {
    std::vector<std::string> names;
    for (const char* name : {"halftone", "dots", "st_derivative_probe", "float_env_probe", "flow_noise"}) {
        if (qs::find_program(name)) names.emplace_back(name);
    }
    if (names.empty()) names.emplace_back(qs::catalogue().at(0)->info().name);
    return names;
}

// The child: load and render; exit 0 rendered, 1 a message (written to `messages`).
[[noreturn]] void load_and_render(const fs::path& scene, const std::string& shader, int messages) {
    ::alarm(60);  // a hang ends as SIGALRM: a failure
    int code = 0;
    std::string message;
    try {
        qs::Scene s = qs::load_scene(scene);
        qs::FrameRequest r;
        r.width = 24, r.height = 17;
        r.shader_override = shader;
        r.shading.threads = 2;
        qs::render_frame(s, r);
#if defined(QUADSHADE_HAS_RAYCAST)
        r.backend = qs::Backend::RayCaster;
        r.shading.pairing = qs::QuadPairing::BottomUp;
        qs::render_frame(s, r);
#endif
    } catch (const std::exception& e) {
        message = e.what();
        code = 1;
    }
    message += '\n';
    if (::write(messages, message.data(), message.size()) < 0) code = 3;
    ::_exit(code);
}

// "FILE: field[3].x: what 12": the message without the file and with numbers as #, to group.
std::string kind(std::string m) {
    if (const auto colon = m.find(": "); colon != std::string::npos && m.find(".gltf") < colon) m = m.substr(colon + 2);
    std::string out;
    for (char c : m) {
        if (c >= '0' && c <= '9') {
            if (out.empty() || out.back() != '#') out += '#';
        } else if (c != '\n') {
            out += c;
        }
    }
    return out.substr(0, 110);
}

// One scene loaded and rendered in a child process: its exit status, the message it sent, and
// what it wrote to stderr (a sanitizer's report). None where the pipe could not be made.
struct ChildRun {
    int status = 0;
    std::string message, error_output;
};
std::optional<ChildRun> run_in_child(const fs::path& scene, const std::string& shader, const fs::path& work) {
    int pipe_fds[2];
    if (::pipe(pipe_fds) != 0) return std::nullopt;
    const fs::path errors = work / "stderr.txt";
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(pipe_fds[0]);
        const int err = ::open(errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (err < 0 || ::dup2(err, 2) < 0) ::_exit(3);
        load_and_render(scene, shader, pipe_fds[1]);
    }
    ::close(pipe_fds[1]);
    ChildRun run;
    char buf[4096];
    for (ssize_t r; (r = ::read(pipe_fds[0], buf, sizeof buf)) > 0;) run.message.append(buf, std::size_t(r));
    ::close(pipe_fds[0]);
    ::waitpid(pid, &run.status, 0);
    run.error_output = slurp(errors);
    return run;
}

// What went wrong in a child, or null where it rendered or refused the scene with a message.
const char* failure_of(const ChildRun& run) {
    const int status = run.status;
    const bool report = run.error_output.find("Sanitizer") != std::string::npos ||
                        run.error_output.find("runtime error:") != std::string::npos;
    return report                                               ? "sanitizer report"
           : WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM ? "hang (60 s)"
           : WIFSIGNALED(status)                                ? "signal"
           : WEXITSTATUS(status) > 1                            ? "exit"
                                                                : nullptr;
}

// The run's counts, and the most frequent kinds of refusal message.
void print_summary(unsigned seed, int count, int rendered, int refused, const std::map<std::string, int>& failures,
                   const std::map<std::string, int>& kinds) {
    std::vector<std::pair<int, std::string>> top;
    for (const auto& [k, c] : kinds) top.emplace_back(c, k);
    std::sort(top.rbegin(), top.rend());
    auto failed = [&](const char* what) { return failures.count(what) ? failures.at(what) : 0; };
    std::printf("mutation run, seed %u: %d scenes, %d rendered by both backends, %d refused with a message; "
                "%d sanitizer reports, %d signals, %d hangs, %d other exits\n",
                seed, count, rendered, refused, failed("sanitizer report"), failed("signal"), failed("hang (60 s)"),
                failed("exit"));
    std::printf("%zu kinds of message; the most frequent:\n", kinds.size());
    for (std::size_t i = 0; i < top.size() && i < 15; ++i) std::printf("  %5d  %s\n", top[i].first, top[i].second.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: quadshade-mutation-run COUNT [SEED] [KEEP_DIR]\n");
        return 2;
    }
    const int count = std::atoi(argv[1]);
    const unsigned seed = argc > 2 ? unsigned(std::strtoul(argv[2], nullptr, 10)) : 23u;
    const fs::path keep = argc > 3 ? fs::path(argv[3]) : fs::temp_directory_path() / "quadshade-mutation-failures";
    const fs::path work = fs::temp_directory_path() / ("quadshade-mutation-" + std::to_string(::getpid()));
    fs::create_directories(work / "textures");
    fs::copy_file(kAssets / "textures/halftone-source.png", work / "textures/halftone-source.png");
    const char* names[] = {"figure-1.1", "table-1.1-plane"};
    json docs[2];
    std::string bins[2];
    for (int i = 0; i < 2; ++i) {
        docs[i] = json::parse(slurp(kAssets / (std::string(names[i]) + ".gltf")));
        bins[i] = slurp(kAssets / (std::string(names[i]) + ".bin"));
    }
    const std::vector<std::string> shader_names = shaders();
    Mutator m(seed);
    int rendered = 0, refused = 0;
    std::map<std::string, int> failures;  // sanitizer report, signal, hang, exit
    std::map<std::string, int> kinds;
    for (int n = 0; n < count; ++n) {
        const int which = m.pick(2);
        json doc = docs[which];
        std::string bin = bins[which];
        for (int k = 1 + m.pick(4); k > 0; --k) m.mutate(doc);
        if (m.pick(3) == 0) m.mutate(bin);
        const fs::path scene = work / "scene.gltf";
        std::ofstream(scene, std::ios::binary) << doc.dump();
        std::ofstream(work / (std::string(names[which]) + ".bin"), std::ios::binary) << bin;
        const std::string shader = shader_names[std::size_t(m.pick(int(shader_names.size())))];
        const std::optional<ChildRun> run = run_in_child(scene, shader, work);
        if (!run) return 3;
        const int status = run->status;
        const std::string& message = run->message;
        const char* failure = failure_of(*run);
        if (!failure && WEXITSTATUS(status) == 0) {
            ++rendered;
        } else if (!failure) {
            ++refused;
            ++kinds[kind(message)];
        } else {
            ++failures[failure];
            const fs::path kept = keep / std::to_string(n);
            fs::create_directories(kept);
            fs::copy(work, kept, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
            std::printf("scene %d (%s, shader %s): %s (%s %d); kept in %s\n", n, names[which], shader.c_str(), failure,
                        WIFSIGNALED(status) ? "signal" : "exit", WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status),
                        kept.c_str());
        }
    }
    fs::remove_all(work);
    print_summary(seed, count, rendered, refused, failures, kinds);
    return failures.empty() ? 0 : 1;
}
