// Writing recordings (src/recording/commonroad_writer.h, trace_recording.h): what the writer
// writes the reader reads back unchanged, and a trace laid on a bend keeps its lanes, widths and
// the vehicles' Frenet coordinates.
#include <cmath>

#include <gtest/gtest.h>

#include "recording/commonroad_reader.h"
#include "recording/commonroad_writer.h"
#include "recording/frenet_track.h"
#include "recording/road_layout.h"
#include "recording/trace_recording.h"
#include "synthetic_recording.h"

namespace mg {
namespace {

void expect_same(const Recording& a, const Recording& b) {
  ASSERT_EQ(a.lanelets.size(), b.lanelets.size());
  for (std::size_t i = 0; i < a.lanelets.size(); ++i) {
    EXPECT_EQ(a.lanelets[i].id, b.lanelets[i].id);
    EXPECT_EQ(a.lanelets[i].left_bound.size(), b.lanelets[i].left_bound.size());
    EXPECT_EQ(a.lanelets[i].adjacent_left, b.lanelets[i].adjacent_left);
    EXPECT_EQ(a.lanelets[i].adjacent_right, b.lanelets[i].adjacent_right);
  }
  ASSERT_EQ(a.vehicles.size(), b.vehicles.size());
  for (std::size_t i = 0; i < a.vehicles.size(); ++i) {
    ASSERT_EQ(a.vehicles[i].states.size(), b.vehicles[i].states.size());
    for (std::size_t k = 0; k < a.vehicles[i].states.size(); ++k) {
      EXPECT_NEAR(a.vehicles[i].states[k].x_m, b.vehicles[i].states[k].x_m, 1e-6);
      EXPECT_NEAR(a.vehicles[i].states[k].y_m, b.vehicles[i].states[k].y_m, 1e-6);
      EXPECT_NEAR(*a.vehicles[i].states[k].speed_mps, *b.vehicles[i].states[k].speed_mps, 1e-6);
      EXPECT_EQ(a.vehicles[i].states[k].time_step, b.vehicles[i].states[k].time_step);
    }
  }
}

TEST(CommonRoadWriter, WhatItWritesReadsBackUnchanged) {
  const Recording r = parse_recording(test::synthetic_recording_xml({test::lane_changer(4, 50, 20, -1.75, 1.75, 2.0, 40)}), "a.xml");
  const Recording back = parse_recording(recording_to_xml(r), "b.xml");
  EXPECT_EQ(back.version, "2020a");
  EXPECT_EQ(back.benchmark_id, r.benchmark_id);
  expect_same(r, back);
}

ObservedTrace two_vehicle_trace() {
  ObservedTrace t;
  t.name = "bend";
  t.road.main_lanes = 2;
  t.road.side_lane_start_x_m = 0;
  t.road.side_lane_end_x_m = 150;
  t.vehicles = {VehicleDeclaration{0, {}, {}, false}, VehicleDeclaration{1, {}, Limits{1.0, 3.0, 6.0, 0.2, 0.8}, false}};
  for (int i = 0; i < 50; ++i) {
    const double time = 0.1 * i;
    t.steps.push_back({time, {ObservedState{10 + 20 * time, -3.5, 0, 20, 0, 0}, ObservedState{40 + 15 * time, 3.5, 0, 15, 0, 0}}});
  }
  return t;
}

TEST(TraceRecording, ABendKeepsLanesAndFrenetCoordinates) {
  const ObservedTrace t = two_vehicle_trace();
  const TraceRecording tr = trace_to_recording(t, 300.0);
  EXPECT_EQ(tr.limits_by_type.size(), 2u);  // two sets of declared limits: car and truck
  EXPECT_EQ(tr.recording.vehicles[1].type, "truck");
  EXPECT_EQ(tr.recording.vehicles[1].id, kTraceObstacleIdBase + 1);
  const Recording r = parse_recording(recording_to_xml(tr.recording), "bend.xml");
  const RoadLayout road = build_road_layout(r);
  EXPECT_NEAR(road.lane_width_m, 3.5, 1e-3);
  EXPECT_EQ(road.main_lanes.size(), 2u);
  EXPECT_NEAR(road.reference.shape().max_abs_curvature_per_m, 1.0 / 300, 2e-4);
  const FrenetTrack ego = project_track(r.vehicles[0], road.reference, r.time_step_s, 3);
  const FrenetTrack other = project_track(r.vehicles[1], road.reference, r.time_step_s, 3);
  for (std::size_t i = 0; i < ego.states.size(); ++i) {
    EXPECT_NEAR(ego.states[i].d_m, -3.5, 0.02);
    EXPECT_NEAR(other.states[i].d_m, 3.5, 0.02);
    EXPECT_NEAR(other.states[i].s_m - ego.states[i].s_m, 30 - 5 * 0.1 * static_cast<double>(i), 0.05);
    EXPECT_NEAR(ego.states[i].vs_mps, 20, 0.05);  // the recorded speed, outside the bend, back to ds/dt
  }
}

}  // namespace
}  // namespace mg
