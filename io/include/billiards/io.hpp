/// \file
/// billiards::io, every file format of billiards in one include: a shot's events (JSON), trajectories
/// (CSV), the shot as SVG and as an animated HTML page, shot and table setup files
/// (billiards/io/shot.hpp, billiards/io/table.hpp), gas snapshots and measurements
/// (billiards/io/snapshots.hpp, billiards/io/gas.hpp), line plots (billiards/io/plot.hpp) and atomic
/// writing (billiards/io/atomic_file.hpp). docs/io.md.
#pragma once

#include <billiards/io/atomic_file.hpp>
#include <billiards/io/gas.hpp>
#include <billiards/io/json.hpp>
#include <billiards/io/plot.hpp>
#include <billiards/io/shot.hpp>
#include <billiards/io/snapshots.hpp>
#include <billiards/io/table.hpp>
