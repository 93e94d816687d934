// SPDX-License-Identifier: MIT
// Fuzz target: the .scad lexer, parser and evaluator on arbitrary text. Evaluation runs under
// small limits (steps, elements, nodes, string bytes, call depth) so no input runs long, on a
// thread with a stack of its own as importScad does. include<>/use<>/import() find only the
// project's scenes/ library: the input is anchored in an empty scratch folder, and inputs that
// name device or process files are skipped.
#include <pthread.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "importers/scad/lang/evaluator.h"
#include "importers/scad/lang/parser.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

constexpr size_t kStackBytes = size_t{64} << 20;

struct Job {
    std::string_view text;
};

void evaluateText(std::string_view text) {
    using namespace rt::scad;
    rt::DiagnosticSink diag;
    SourceLoader loader({SCADRAY_LIBRARY_DIR}, diag);
    std::string anchor = (rt::fuzz::scratchDir() / "fuzz.scad").string();
    std::shared_ptr<SourceFile> file = parseSource(std::string(text), anchor, loader);
    EvalLimits limits;
    limits.maxCallDepth = 200;
    limits.maxSteps = 20'000;
    limits.maxLiveElements = 100'000;
    limits.maxLiveStringBytes = 1 << 20;
    limits.maxNodes = 5'000;
    limits.maxStringLength = 64 << 10;
    limits.stackReserveBytes = 8u << 20;  // sanitizer frames are large
    limits.maxGeometryWork = 50'000;      // minkowski() and projection() of big children
    Evaluator evaluator(diag, limits);
    rt::ir::Scene scene = evaluator.evaluate(*file, loader);
    (void)scene;
}

bool namesSystemFiles(std::string_view text) {
    for (const char *bad : {"/dev", "/proc", "/sys", "/run"})
        if (text.find(bad) != std::string_view::npos) return true;
    return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::string_view text(reinterpret_cast<const char *>(data), size);
    if (namesSystemFiles(text)) return 0;
    rt::fuzz::scratchDir();
    Job job{text};
    auto entry = [](void *p) -> void * {
        auto *j = static_cast<Job *>(p);
        rt::fuzz::expectCleanFailure([&] { evaluateText(j->text); });
        return nullptr;
    };
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, kStackBytes);
    pthread_t thread;
    if (pthread_create(&thread, &attr, entry, &job) != 0) rt::fuzz::fail("pthread_create");
    pthread_attr_destroy(&attr);
    pthread_join(thread, nullptr);
    return 0;
}
