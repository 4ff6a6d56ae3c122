#pragma once
// The device limits the compute passes must respect: work groups per dispatch and storage block
// size (GL_MAX_COMPUTE_WORK_GROUP_COUNT, GL_MAX_SHADER_STORAGE_BLOCK_SIZE).
#include <cstddef>

#include "render/gl/shader_program.h"

namespace gps {

/// Runs `program` (current) over `count` invocations in groups of kWorkGroupSize, in as many
/// dispatches as GL_MAX_COMPUTE_WORK_GROUP_COUNT (x), or a lower `group_limit` > 0, requires; the
/// program's `u_first` uniform gets each dispatch's first invocation.
void dispatch_split(const ShaderProgram& program, int count, int group_limit);

/// One pass of a compute program over `count` items, all of them or (use_list) those of an uploaded
/// list: makes it current, sets its `u_count` and `u_use_list`, dispatches (dispatch_split) and puts
/// a storage barrier after its writes; other uniforms are the caller's, set before.
void run_compute_pass(const ShaderProgram& program, int count, bool use_list, int group_limit);

/// Throws gps::Error naming the mesh and the figures if `bytes` of `what`, read by a shader as one
/// storage block, exceed GL_MAX_SHADER_STORAGE_BLOCK_SIZE (or a lower `limit` > 0).
void check_storage_fits(const char* what, size_t bytes, int n_vertices, int n_faces, long long limit);

}  // namespace gps
