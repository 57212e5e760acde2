"""Robot base algorithms: maps, costmap, planner, simulated base and LiDAR, AMCL.

Pure algorithms on numpy/scipy; nothing here knows about the assistant (only errors.py is
shared). The adapter in assistantx.adapters.robot.navigator puts them behind RobotBase.
"""

from assistantx.nav.amcl import AmclParams, ParticleFilter, PoseEstimate
from assistantx.nav.anchors import Anchor, load_anchors, save_anchors
from assistantx.nav.costmap import Costmap, InflationParams
from assistantx.nav.lidar import LaserScan, Lidar, LidarParams
from assistantx.nav.motion_model import OdometryNoise, motion_model
from assistantx.nav.navigation import NavigationParams, Navigator
from assistantx.nav.occupancy_map import OccupancyMap, load_map, save_map
from assistantx.nav.planner import GridPlanner, Path, PlannerParams

__all__ = [
    "AmclParams",
    "Anchor",
    "Costmap",
    "GridPlanner",
    "InflationParams",
    "LaserScan",
    "Lidar",
    "LidarParams",
    "NavigationParams",
    "Navigator",
    "OccupancyMap",
    "OdometryNoise",
    "ParticleFilter",
    "Path",
    "PlannerParams",
    "PoseEstimate",
    "load_anchors",
    "load_map",
    "motion_model",
    "save_anchors",
    "save_map",
]
