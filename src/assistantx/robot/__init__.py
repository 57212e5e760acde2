"""Robot base algorithms: maps, costmap, planner, simulated base and LiDAR, AMCL.

Pure algorithms on numpy/scipy; nothing here knows about the assistant (only errors.py is
shared). The adapter in assistantx.adapters.robot.navigator puts them behind RobotBase.
"""

from assistantx.robot.amcl import AmclParams, ParticleFilter, PoseEstimate
from assistantx.robot.anchors import Anchor, load_anchors, save_anchors
from assistantx.robot.costmap import Costmap, InflationParams
from assistantx.robot.lidar import LaserScan, Lidar, LidarParams
from assistantx.robot.motion_model import OdometryNoise, motion_model
from assistantx.robot.navigation import NavigationParams, Navigator
from assistantx.robot.occupancy_map import OccupancyMap, load_map, save_map
from assistantx.robot.planner import GridPlanner, Path, PlannerParams

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
