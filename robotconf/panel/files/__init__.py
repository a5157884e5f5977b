"""Files: the bound file that keeps the work, save and load, and the exports."""

from ._atomic_file import write_atomically
from ._binding import SAVE_INTERVAL, FileBinding, bound_path, flush_all
from ._export_files import (
    FIGURE_FORMATS,
    file_stem,
    report_zip,
    robot_figure,
    scene_page,
    step_latex,
)
from ._images import data_uri, download_link, figure_png, responsive_image
from ._setup_io import setup_from, setup_parts, setup_to_json
from ._view import EXPORTS, FilesView, robot_stem, size_text

__all__ = [
    "FileBinding",
    "SAVE_INTERVAL",
    "bound_path",
    "flush_all",
    "write_atomically",
    "FilesView",
    "EXPORTS",
    "robot_stem",
    "size_text",
    "setup_from",
    "setup_parts",
    "setup_to_json",
    "FIGURE_FORMATS",
    "file_stem",
    "report_zip",
    "robot_figure",
    "scene_page",
    "step_latex",
    "data_uri",
    "download_link",
    "figure_png",
    "responsive_image",
]
