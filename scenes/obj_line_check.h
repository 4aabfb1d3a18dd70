// The checks tinyobjloader does not make, done on the OBJ text before it parses it: it reads
// `v nan 0 0`, `v 1 2` and `v a b c` as zeros, and wraps a face index beyond 32 bits (so
// `f 1 2 4294967299` becomes vertex 3). Each of those is an error here that names the line.
#pragma once

#include <istream>
#include <string>

namespace strata::scenes {

// Reads `in` to the end and rewinds it. Throws SceneError "<source>:<line>: ..." for a vertex
// position that is not 3 finite numbers (a w or an RGB colour may follow), and for a face,
// line or point index that is not a non-zero integer naming a vertex the file defines, and
// for a concave face of more than 3 vertices (tinyobjloader triangulates faces as fans, which
// covers the wrong area for a concave one: refused rather than rendered wrong).
void check_obj_lines(std::istream& in, const std::string& source);

// The same for a .mtl: tinyobjloader reads `Kd nan` as it comes, and the loader's clamp made it
// a silent black (issue 39). Reads `in` to the end and rewinds it; throws SceneError
// "<source>:<line>: material '<name>': <field> value '<v>' is not a finite number" for a
// numeric field's value that is a number but NaN or beyond float (a word, as in
// `Kd spectral file.rfl`, is left to tinyobjloader).
void check_mtl_lines(std::istream& in, const std::string& source);

}  // namespace strata::scenes
