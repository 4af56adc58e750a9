#pragma once
/// @file shipped_file.hpp
/// The files the commands take by path (--config, --robot, --gait) as the docs spell them,
/// configs/..., from any folder: such a relative path that names nothing under the working
/// directory names the shipped file (io/data_dir.hpp), as a reference folder's robot is found
/// (sim/scenario/reference_folder.hpp). A user's own configs/ under the working directory come
/// first.
#include <CLI/CLI.hpp>

namespace gaitopt::apps {

/// The transform of such an option: a path under configs/ becomes the shipped file of that path
/// when the working directory has none and the shipped one exists; any other path is kept.
CLI::Validator orShippedFile();

}  // namespace gaitopt::apps
