"""Robot base algorithms: maps, costmap, planner, simulated base and LiDAR, AMCL.

Pure algorithms on numpy/scipy; nothing here knows about the assistant (only errors.py is
shared). The adapter in assistantx.adapters.robot.navigator puts them behind RobotBase.
"""

from assistantx.adapters.robot.nav.amcl import AmclParams, ParticleFilter, PoseEstimate
from assistantx.adapters.robot.nav.anchors import Anchor, load_anchors, save_anchors
from assistantx.adapters.robot.nav.costmap import Costmap, InflationParams
from assistantx.adapters.robot.nav.lidar import LaserScan, Lidar, LidarParams
from assistantx.adapters.robot.nav.motion_model import OdometryNoise, motion_model
from assistantx.adapters.robot.nav.navigation import NavigationParams, Navigator
from assistantx.adapters.robot.nav.occupancy_map import OccupancyMap, load_map, save_map
from assistantx.adapters.robot.nav.planner import GridPlanner, Path, PlannerParams

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
