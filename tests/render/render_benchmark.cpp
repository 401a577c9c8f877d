// Where the time of a 640x480 frame goes: drawing, PNG encoding (at the chosen and at other stb settings),
// and frames per second end to end with FrameWriter's pool. Figures are in docs/rendering.md.

#include "physltl/render/frame_writer.h"
#include "physltl/render/png.h"
#include "physltl/render/renderer.h"
#include "physltl/scenario/load.h"

#include <benchmark/benchmark.h>
#include <stb_image_write.h>
#include <sys/resource.h>

#include <cstdint>
#include <filesystem>
#include <string>

namespace physltl::render {
namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 480;

scenario::World rooms() {
  return scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/rooms.lua");
}

Overlay frame_legend() {
  Overlay overlay;
  overlay.legend = {"F(p1 & F(p2 & F(p3 | p4)))", "automaton state 1", "t = 1.23 s"};
  return overlay;
}

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// The robot moves a little each frame, like a replayed plan.
scenario::EnvironmentState state_at(const scenario::World& world, int frame) {
  scenario::EnvironmentState state = scenario::EnvironmentState::initial(world);
  state.robot_position.x() += 0.01 * (frame % 300);
  return state;
}

void BM_Draw(benchmark::State& bench) {
  const scenario::World world = rooms();
  Renderer renderer(world, kWidth, kHeight);
  const Overlay overlay = frame_legend();
  int frame = 0;
  for (auto _ : bench) benchmark::DoNotOptimize(renderer.draw(state_at(world, frame++), overlay, View::kPerspective));
}
BENCHMARK(BM_Draw)->Unit(benchmark::kMillisecond);

void BM_EncodePng(benchmark::State& bench) {
  const scenario::World world = rooms();
  const Image image = Renderer(world, kWidth, kHeight).draw(state_at(world, 0), frame_legend(), View::kPerspective);
  std::size_t bytes = 0;
  for (auto _ : bench) bytes = encode_png(image).size();
  bench.counters["KB"] = static_cast<double>(bytes) / 1024;
}
BENCHMARK(BM_EncodePng)->Unit(benchmark::kMillisecond);

void BM_FramesEndToEnd(benchmark::State& bench) {
  const scenario::World world = rooms();
  Renderer renderer(world, kWidth, kHeight);
  const Overlay overlay = frame_legend();
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "physltl_render_benchmark";
  std::filesystem::create_directories(folder);
  constexpr int kFrames = 120;
  const double cpu_before = process_cpu_seconds();
  for (auto _ : bench) {
    FrameWriter writer(folder);
    for (int i = 0; i < kFrames; ++i) writer.add(renderer.draw(state_at(world, i), overlay, View::kPerspective));
    writer.finish();
  }
  const double frames = static_cast<double>(bench.iterations()) * kFrames;
  bench.SetItemsProcessed(static_cast<std::int64_t>(frames));  // items/s = frames/s
  // CPU of every thread (drawing, llvmpipe, encoders) per frame: on a busy shared machine the wall-clock
  // rate says more about the neighbours than about us; cores / this is the rate on an idle machine.
  bench.counters["cpu_ms_per_frame"] = 1000 * (process_cpu_seconds() - cpu_before) / frames;
  std::filesystem::remove_all(folder);
}
BENCHMARK(BM_FramesEndToEnd)->Unit(benchmark::kMillisecond)->UseRealTime();

// The alternatives behind the chosen setting: stb's deflate level and row filter (-1: stb's per-row search).
// Sets stb's globals directly, so it is registered last (benchmarks run in order) and runs on one thread.
void BM_EncodePngStbSettings(benchmark::State& bench) {
  const scenario::World world = rooms();
  const Image image = Renderer(world, kWidth, kHeight).draw(state_at(world, 0), frame_legend(), View::kPerspective);
  stbi_write_png_compression_level = static_cast<int>(bench.range(0));
  stbi_write_force_png_filter = static_cast<int>(bench.range(1));
  int bytes = 0;
  auto count = [](void* total, void*, int size) { *static_cast<int*>(total) += size; };
  for (auto _ : bench) {
    bytes = 0;
    stbi_write_png_to_func(count, &bytes, image.width, image.height, 3, image.rgb.data(), image.width * 3);
  }
  bench.counters["KB"] = bytes / 1024.0;
}
BENCHMARK(BM_EncodePngStbSettings)
    ->ArgsProduct({{5, 8}, {-1, 0, 1, 2, 3, 4}})  // stb treats levels below 5 as 5
    ->ArgNames({"level", "filter"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace physltl::render

BENCHMARK_MAIN();
