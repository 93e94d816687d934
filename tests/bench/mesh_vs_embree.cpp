// SPDX-License-Identifier: MIT
// Benchmark (not a test): scadray's triangle-mesh BVH side by side with Embree 3 on the same
// mesh and the same rays. Prints BVH build time (with the leaf-ordered triangle copy) on 1 and
// 2 threads, closest-hit rays per CPU-second (one thread) for 640x480 camera rays and for
// random rays, and bytes per triangle.
// Built with Embree where CMake finds it (SCADRAY_HAVE_EMBREE); otherwise prints scadray only.
// Run: build/tests/mesh_vs_embree [LEVELS] [--double]   (icosphere of 20 * 4^LEVELS triangles,
// default 8; positions rounded to floats, as STL and glTF give them, or with --double as
// computed, so scadray's leaves keep vertex indices while Embree gets them rounded)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/geometry/triangle_mesh.h"
#include "core/math/rng.h"
#include "support/mesh_builder.h"

#ifdef SCADRAY_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace rt {
namespace {

double wallNow() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

double threadCpuNow() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

double processCpuNow() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/// Best of `repeat` wall times of f(), and the CPU time of that run (all threads).
double bestWall(int repeat, const std::function<void()> &f, double *cpu) {
    double best = 1e300;
    for (int i = 0; i < repeat; ++i) {
        double t0 = wallNow(), c0 = processCpuNow();
        f();
        double wall = wallNow() - t0;
        if (wall < best) {
            best = wall;
            *cpu = processCpuNow() - c0;
        }
    }
    return best;
}

/// 640x480 pinhole camera rays at the unit sphere from a distance of 3, 40 degrees vertical.
std::vector<Ray> cameraRays() {
    Vec3 eye(0.9, 1.2, 2.6), up(0, 1, 0);
    Vec3 w = normalize(Vec3(0) - eye), u = normalize(cross(w, up)), v = cross(u, w);
    double h = std::tan(20 * kPi / 180), aspect = 640.0 / 480;
    std::vector<Ray> rays;
    rays.reserve(640 * 480);
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < 640; ++x) {
            double sx = ((x + 0.5) / 640 * 2 - 1) * h * aspect, sy = (1 - (y + 0.5) / 480 * 2) * h;
            rays.emplace_back(eye, normalize(w + u * sx + v * sy));
        }
    return rays;
}

/// Rays from random points on a sphere of radius 3 towards random points of [-1.2, 1.2]^3.
std::vector<Ray> randomRays(size_t n) {
    Rng rng(7);
    std::vector<Ray> rays;
    rays.reserve(n);
    while (rays.size() < n) {
        Vec3 o(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1);
        if (lengthSquared(o) > 1 || lengthSquared(o) < 1e-6) continue;
        o = normalize(o) * 3;
        Vec3 target(rng.uniform() * 2.4 - 1.2, rng.uniform() * 2.4 - 1.2,
                    rng.uniform() * 2.4 - 1.2);
        rays.emplace_back(o, normalize(target - o));
    }
    return rays;
}

struct TraceResult {
    double raysPerSecond = 0;
    size_t hits = 0;
    std::vector<int> triangle;  ///< closest triangle per ray, -1 for a miss
};

TraceResult traceScadray(const TriangleMesh &mesh, const std::vector<Ray> &rays) {
    TraceResult r;
    r.triangle.assign(rays.size(), -1);
    double best = 1e300;
    for (int rep = 0; rep < 3; ++rep) {
        size_t hits = 0;
        double t0 = threadCpuNow();
        for (size_t i = 0; i < rays.size(); ++i) {
            TriangleMesh::Hit hit;
            if (mesh.closest(rays[i], 0, kInfinity, &hit)) {
                ++hits;
                r.triangle[i] = static_cast<int>(hit.triangle);
            }
        }
        best = std::min(best, threadCpuNow() - t0);
        r.hits = hits;
    }
    r.raysPerSecond = rays.size() / best;
    return r;
}

#ifdef SCADRAY_HAVE_EMBREE
struct EmbreeMemory {
    long long current = 0, peak = 0;
};

bool monitor(void *user, ssize_t bytes, bool) {
    auto *m = static_cast<EmbreeMemory *>(user);
    m->current += bytes;
    m->peak = std::max(m->peak, m->current);
    return true;
}

struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    EmbreeMemory memory;
    double buildSeconds = 0, buildCpu = 0;
    ~EmbreeScene() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

/// Embree's device configuration: the thread count, then EMBREE_CONFIG where set (for example
/// "isa=sse4.2" to compare at one instruction set; Embree ignores settings it does not know, so
/// the configuration is printed, and "verbose=2" shows the kernels it picked).
std::string embreeConfig(int threads) {
    std::string config = "threads=" + std::to_string(threads);
    if (const char *extra = std::getenv("EMBREE_CONFIG"); extra && *extra)
        config += std::string(",") + extra;
    return config;
}

/// Builds the scene with the vertex and index buffers shared (not counted as Embree's memory).
std::unique_ptr<EmbreeScene> embreeBuild(const std::vector<float> &vertices,
                                         const std::vector<uint32_t> &indices, int threads) {
    auto s = std::make_unique<EmbreeScene>();
    std::string config = embreeConfig(threads);
    s->device = rtcNewDevice(config.c_str());
    if (!s->device) {
        std::fprintf(stderr,
                     "mesh_vs_embree: Embree refused the device configuration \"%s\" (error %d)\n",
                     config.c_str(), static_cast<int>(rtcGetDeviceError(nullptr)));
        std::exit(1);
    }
    rtcSetDeviceMemoryMonitorFunction(s->device, monitor, &s->memory);
    s->scene = rtcNewScene(s->device);
    RTCGeometry g = rtcNewGeometry(s->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices.data(), 0,
                               3 * sizeof(float), (vertices.size() - 1) / 3);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices.data(), 0,
                               3 * sizeof(uint32_t), indices.size() / 3);
    rtcCommitGeometry(g);
    rtcAttachGeometry(s->scene, g);
    rtcReleaseGeometry(g);
    s->memory = {};
    double t0 = wallNow(), c0 = processCpuNow();
    rtcCommitScene(s->scene);
    s->buildSeconds = wallNow() - t0;
    s->buildCpu = processCpuNow() - c0;
    return s;
}

TraceResult traceEmbree(RTCScene scene, const std::vector<Ray> &rays) {
    TraceResult r;
    r.triangle.assign(rays.size(), -1);
    double best = 1e300;
    for (int rep = 0; rep < 3; ++rep) {
        size_t hits = 0;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        double t0 = threadCpuNow();
        for (size_t i = 0; i < rays.size(); ++i) {
            RTCRayHit rh;
            rh.ray.org_x = static_cast<float>(rays[i].o.x);
            rh.ray.org_y = static_cast<float>(rays[i].o.y);
            rh.ray.org_z = static_cast<float>(rays[i].o.z);
            rh.ray.dir_x = static_cast<float>(rays[i].d.x);
            rh.ray.dir_y = static_cast<float>(rays[i].d.y);
            rh.ray.dir_z = static_cast<float>(rays[i].d.z);
            rh.ray.tnear = 0;
            rh.ray.tfar = INFINITY;
            rh.ray.mask = ~0u;
            rh.ray.flags = 0;
            rh.ray.time = 0;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene, &context, &rh);
            if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
                ++hits;
                r.triangle[i] = static_cast<int>(rh.hit.primID);
            }
        }
        best = std::min(best, threadCpuNow() - t0);
        r.hits = hits;
    }
    r.raysPerSecond = rays.size() / best;
    return r;
}
#endif

double agreement(const TraceResult &a, const TraceResult &b) {
    size_t same = 0;
    for (size_t i = 0; i < a.triangle.size(); ++i) same += a.triangle[i] == b.triangle[i];
    return 100.0 * same / a.triangle.size();
}

int run(int levels, bool doublePositions) {
    // Positions rounded to floats, as an STL or glTF file gives them, so both libraries trace
    // exactly the same triangles
    auto mesh = test::icosphere(levels, 1);
    if (!doublePositions) mesh = test::inFloats(mesh);
    size_t tris = mesh->triangles.size();
    std::printf("icosphere: %zu triangles, %zu vertices\n", tris, mesh->positions.size());
    double meshBytes = (mesh->positions.size() * sizeof(Vec3) + tris * sizeof(mesh->triangles[0])) /
                       static_cast<double>(tris);

    double cpu1 = 0, cpu2 = 0;
    // The BVH and the leaf-ordered copy of the triangles that its leaves read: together they
    // are what Embree's build makes (its leaves hold the triangles)
    auto buildBvh = [&](int threads) {
        WideBvh bvh = TriangleMesh::buildBvh(*mesh, threads);
        auto floats = TriangleMesh::floatLeaves(*mesh, bvh, threads);
        if (floats.empty()) auto leaves = TriangleMesh::leafOrder(*mesh, bvh);
    };
    double build1 = bestWall(
        3, [&] { buildBvh(1); }, &cpu1);
    double build2 = bestWall(
        3, [&] { buildBvh(2); }, &cpu2);
    auto tm = std::make_unique<TriangleMesh>(mesh);
    double bvhBytes = tm->extraBytes() / static_cast<double>(tris);
    {
        size_t leaves = 0, children = 0;
        for (const auto &n : tm->bvh().nodes())
            for (uint32_t c : n.child) {
                children += c != WideBvh::kEmpty;
                leaves += c != WideBvh::kEmpty && (c & WideBvh::kLeaf);
            }
        std::printf(
            "scadray BVH: %zu nodes of %zu bytes, %.2f children a node, %zu leaves of %.2f "
            "triangles, "
            "depth %d\n",
            tm->bvh().nodes().size(), sizeof(WideBvh::Node),
            children / static_cast<double>(tm->bvh().nodes().size()), leaves,
            tris / static_cast<double>(leaves), tm->bvh().depth());
        std::printf("scadray leaves hold %s\n",
                    tm->floatLeaves().empty() ? "vertex indices" : "float vertices");
    }
    auto camera = cameraRays();
    auto random = randomRays(camera.size());
    TraceResult sc = traceScadray(*tm, camera), sr = traceScadray(*tm, random);

#ifdef SCADRAY_HAVE_EMBREE
    std::printf("Embree device configuration: %s\n", embreeConfig(1).c_str());
#endif
    std::printf("\n%-34s %14s", "", "scadray");
#ifdef SCADRAY_HAVE_EMBREE
    std::vector<float> vertices;
    for (const auto &p : mesh->positions)
        for (int k = 0; k < 3; ++k) vertices.push_back(static_cast<float>(p[k]));
    vertices.push_back(0);  // Embree reads vertices with 16-byte loads
    std::vector<uint32_t> indices;
    for (const auto &t : mesh->triangles) indices.insert(indices.end(), t.begin(), t.end());
    double e1 = 1e300, e2 = 1e300, ecpu1 = 0, ecpu2 = 0;
    for (int rep = 0; rep < 3; ++rep) {
        auto a = embreeBuild(vertices, indices, 1);
        if (a->buildSeconds < e1) e1 = a->buildSeconds, ecpu1 = a->buildCpu;
        auto b = embreeBuild(vertices, indices, 2);
        if (b->buildSeconds < e2) e2 = b->buildSeconds, ecpu2 = b->buildCpu;
    }
    auto es = embreeBuild(vertices, indices, 1);
    TraceResult ec = traceEmbree(es->scene, camera), er = traceEmbree(es->scene, random);
    double embreeBytes = es->memory.current / static_cast<double>(tris);
    std::printf(" %14s %10s\n", "Embree 3", "ratio");
    auto row = [](const char *name, double a, double b, const char *unit) {
        std::printf("%-34s %11.3f %-2s %11.3f %-2s %9.2fx\n", name, a, unit, b, unit, a / b);
    };
    row("BVH build, 1 thread, wall", build1, e1, "s");
    row("BVH build, 1 thread, CPU", cpu1, ecpu1, "s");
    row("BVH build, 2 threads, wall", build2, e2, "s");
    row("BVH build, 2 threads, CPU", cpu2, ecpu2, "s");
    row("camera rays 640x480, 1 thread", sc.raysPerSecond / 1e6, ec.raysPerSecond / 1e6, "M/s");
    row("random rays, 1 thread", sr.raysPerSecond / 1e6, er.raysPerSecond / 1e6, "M/s");
    row("BVH bytes per triangle", bvhBytes, embreeBytes, "B");
    std::printf("%-34s %11.1f B  (shared by both: positions and indices, double here)\n",
                "mesh bytes per triangle", meshBytes);
    std::printf("camera rays hitting: %zu scadray, %zu Embree; same closest triangle %.3f %%\n",
                sc.hits, ec.hits, agreement(sc, ec));
    std::printf("random rays hitting: %zu scadray, %zu Embree; same closest triangle %.3f %%\n",
                sr.hits, er.hits, agreement(sr, er));
    std::printf("Embree peak memory during the build: %.1f B per triangle\n",
                es->memory.peak / static_cast<double>(tris));

    // The same mesh and camera rays moved far from the origin, where a float's spacing (1/128
    // at 1e5) exceeds the triangles' size (about 0.003): which still find the triangle they
    // find at the origin
    const Vec3 far(1e5, 0, 0);
    auto moved = std::make_shared<ir::Mesh>(*mesh);
    for (auto &p : moved->positions) p = p + far;
    std::vector<Ray> movedRays;
    for (const Ray &r : camera) movedRays.emplace_back(r.o + far, r.d);
    TriangleMesh movedMesh(moved);
    TraceResult fs = traceScadray(movedMesh, movedRays);
    std::vector<float> movedVertices;
    for (const auto &p : moved->positions)
        for (int k = 0; k < 3; ++k) movedVertices.push_back(static_cast<float>(p[k]));
    movedVertices.push_back(0);
    auto fe = embreeBuild(movedVertices, indices, 1);
    TraceResult fr = traceEmbree(fe->scene, movedRays);
    std::printf(
        "moved by 1e5: camera rays finding the triangle found at the origin: scadray %.3f %%, "
        "Embree %.3f %%\n",
        agreement(fs, sc), agreement(fr, ec));
#else
    std::printf("\n");
    std::printf("%-34s %11.3f s\n", "BVH build, 1 thread, wall", build1);
    std::printf("%-34s %11.3f s\n", "BVH build, 1 thread, CPU", cpu1);
    std::printf("%-34s %11.3f s\n", "BVH build, 2 threads, wall", build2);
    std::printf("%-34s %11.3f s\n", "BVH build, 2 threads, CPU", cpu2);
    std::printf("%-34s %11.3f M/s\n", "camera rays 640x480, 1 thread", sc.raysPerSecond / 1e6);
    std::printf("%-34s %11.3f M/s\n", "random rays, 1 thread", sr.raysPerSecond / 1e6);
    std::printf("%-34s %11.1f B\n", "BVH bytes per triangle", bvhBytes);
    std::printf("%-34s %11.1f B\n", "mesh bytes per triangle", meshBytes);
    std::printf(
        "(Embree 3 not found at configure time: install libembree-dev and rerun cmake for the "
        "side-by-side figures)\n");
#endif
    return 0;
}

}  // namespace
}  // namespace rt

int main(int argc, char **argv) {
    int levels = 8;
    bool doublePositions = false;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--double")
            doublePositions = true;
        else
            levels = std::atoi(argv[i]);
    }
    return rt::run(levels, doublePositions);
}
