// OBJ import and export.
//
// Sections (grep for "// ----"):
//   messages       "file:line: what" strings
//   numbers        strict number and index parsing (std::from_chars, no locale)
//   scan           one pass over the lines: v / vt / vn / f checked, line numbers kept
//   assemble       tinyobjloader's polygons -> fan triangles with corner UVs (given or planar)
//   parseObj, loadObj
//   saveObj
//
// Why a line scan besides tinyobjloader:
//   - the Debian target tinyobjloader::tinyobjloader is the float build (real_t = float), so its positions
//     would not survive a save/load round trip of double rest positions;
//   - its number parser turns "abc" or "nan" into 0 without a word, and an out-of-range index is only a
//     warning naming the last line of the file.
// So the scan reads every number as a double and names the line of each problem; tinyobjloader then reads
// a sanitized copy of the text (only the checked v/vt/vn/f lines, every other line blanked so the line
// numbers stay) and provides the polygon list. Positions and UVs are taken from the scan.
#include "clothtear/cloth.h" // triangleArea
#include "clothtear/mesh.h"
#include "file_read.h"

#include <tiny_obj_loader.h> // implementation comes from the Debian shared library

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <string_view>
#include <vector>

namespace clothtear {
namespace {

// tinyobjloader stores the corner count of a polygon in an unsigned char.
constexpr size_t kMaxFaceCorners = 255;

// Largest OBJ file loadObj reads. saveObj writes about 360 bytes per particle of a grid (one vt per
// triangle corner; measured at 100 x 100), so this holds an 850 x 850 cloth, far more than the
// simulation runs interactively.
constexpr uintmax_t kMaxObjBytes = uintmax_t(256) << 20;

// ---- messages -----------------------------------------------------------------------------------

std::string atLine(const std::string& path, size_t line, const std::string& what) {
    return path + ":" + std::to_string(line) + ": " + what;
}

// "only 1 vertex is defined" / "only 3 vertices are defined"
std::string defined(size_t count, const char* singular, const char* plural) {
    return "only " + std::to_string(count) + " " + (count == 1 ? singular : plural) +
           (count == 1 ? " is" : " are") + " defined";
}

// "1 number" / "2 numbers"
std::string counted(size_t n, const char* singular, const char* plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

// Appends rather than `"'" + std::string(token) + "'"`: GCC 12 reports a false -Wrestrict on the
// literal + string form (here and in saveObj, key_names.cpp).
std::string quoted(std::string_view token) {
    std::string q;
    q.reserve(token.size() + 2);
    q += '\'';
    q += token;
    q += '\'';
    return q;
}

// ---- numbers ------------------------------------------------------------------------------------

enum class NumberStatus { Ok, NotANumber, OutOfRange };

// Whole token as a double; "nan" and "inf" parse (the caller rejects them with a better message).
NumberStatus parseNumber(std::string_view token, double& out) {
    if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+')
        token.remove_prefix(1);
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, out);
    if (ptr != end || token.empty())
        return NumberStatus::NotANumber;
    if (ec == std::errc::result_out_of_range)
        return NumberStatus::OutOfRange;
    return ec == std::errc() ? NumberStatus::Ok : NumberStatus::NotANumber;
}

// Whole token as an integer (OBJ index, possibly negative).
bool parseIndex(std::string_view token, long long& out) {
    if (token.size() > 1 && token[0] == '+' && token[1] != '-')
        token.remove_prefix(1);
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, out);
    return !token.empty() && ec == std::errc() && ptr == end;
}

std::vector<std::string_view> splitTokens(std::string_view s) {
    std::vector<std::string_view> tokens;
    size_t i = 0;
    while (true) {
        i = s.find_first_not_of(" \t\v\f", i);
        if (i == std::string_view::npos)
            break;
        size_t j = s.find_first_of(" \t\v\f", i);
        if (j == std::string_view::npos)
            j = s.size();
        tokens.push_back(s.substr(i, j - i));
        i = j;
    }
    return tokens;
}

// Splits a face corner at '/' into up to three parts; returns the part count (4 = too many).
size_t splitCorner(std::string_view corner, std::string_view parts[3]) {
    size_t count = 0, start = 0;
    while (true) {
        if (count == 3)
            return 4;
        const size_t slash = corner.find('/', start);
        parts[count++] = corner.substr(start, slash == std::string_view::npos ? slash : slash - start);
        if (slash == std::string_view::npos)
            return count;
        start = slash + 1;
    }
}

// ---- scan ---------------------------------------------------------------------------------------

struct ScannedFace {
    size_t line;    // 1-based line of the `f` statement
    size_t corners; // polygon corner count
    bool hasUV;     // every corner names a vt
};

// A positive index that pointed past the data read so far (OBJ allows forward references); checked
// against the totals at the end of the file.
struct ForwardIndex {
    size_t line;
    long long value;
    bool uv; // vt index, else v index
};

struct Scan {
    std::vector<Vec3d> positions;
    std::vector<Vec2d> uvs;
    std::vector<ScannedFace> faces;
    std::string sanitized; // what tinyobjloader reads: one line per input line
};

class Scanner {
  public:
    Scanner(const std::string& path, Scan& out) : path_(path), out_(out) {}

    // Returns an empty string when every line is acceptable.
    std::string run(std::string_view text) {
        size_t pos = text.starts_with("\xEF\xBB\xBF") ? 3 : 0; // UTF-8 byte order mark
        while (pos < text.size()) {
            size_t end = text.find_first_of("\r\n", pos);
            if (end == std::string_view::npos)
                end = text.size();
            const std::string_view raw = text.substr(pos, end - pos);
            // A line ends at \n, \r\n or a lone \r (as in tinyobjloader).
            pos = end;
            if (pos < text.size())
                pos += (text[pos] == '\r' && pos + 1 < text.size() && text[pos + 1] == '\n') ? 2 : 1;
            ++line_;
            if (std::string err = scanLine(raw); !err.empty())
                return err;
            out_.sanitized += '\n';
        }
        for (const ForwardIndex& f : forward_) {
            const size_t count = f.uv ? out_.uvs.size() : out_.positions.size();
            if (static_cast<unsigned long long>(f.value) > count)
                return atLine(path_, f.line,
                              std::string("face refers to ") + (f.uv ? "texture coordinate " : "vertex ") +
                                  std::to_string(f.value) + " but " +
                                  defined(count, f.uv ? "texture coordinate" : "vertex",
                                          f.uv ? "texture coordinates" : "vertices"));
        }
        if (out_.positions.size() >= kNone)
            return path_ + ": too many vertices (" + std::to_string(out_.positions.size()) + ")";
        if (out_.faces.empty())
            return path_ + (line_ == 0 ? ": no faces (the file is empty)"
                                       : ": no faces (" + std::to_string(line_) +
                                             " lines, none of them an 'f' line)");
        return {};
    }

  private:
    std::string fail(const std::string& what) const { return atLine(path_, line_, what); }

    std::string scanLine(std::string_view raw) {
        for (size_t i = 0; i < raw.size(); ++i) {
            const unsigned char c = static_cast<unsigned char>(raw[i]);
            if ((c < 0x20 && c != '\t' && c != '\v' && c != '\f') || c == 0x7f) {
                char hex[8];
                std::snprintf(hex, sizeof hex, "0x%02x", c);
                return fail("binary data (byte " + std::string(hex) + " at column " + std::to_string(i + 1) +
                            "), not a text OBJ file");
            }
        }
        const std::vector<std::string_view> tokens = splitTokens(raw.substr(0, raw.find('#')));
        if (tokens.empty())
            return {};
        const std::string_view key = tokens[0];
        if (key == "v")
            return scanVertex(tokens);
        if (key == "vt")
            return scanTexCoord(tokens);
        if (key == "vn") {
            out_.sanitized += "vn 0 0 0"; // normals are not used; tinyobjloader only needs to count them
            return {};
        }
        if (key == "f")
            return scanFace(tokens);
        return {}; // o, g, s, usemtl, mtllib, l, p, ...: not needed for a cloth
    }

    // Parses tokens[1..] as numbers; `what` names them in messages ("vertex", "texture coordinate").
    // Checked numbers must be finite and within +-limit (mesh.h: what the float state can hold).
    std::string numbers(const std::vector<std::string_view>& tokens, size_t firstChecked, size_t lastChecked,
                        const std::string& what, double limit, const char* limitText, double* out) {
        for (size_t i = 1; i < tokens.size(); ++i) {
            double value = 0;
            switch (parseNumber(tokens[i], value)) {
            case NumberStatus::NotANumber:
                return fail(what + ": " + quoted(tokens[i]) + " is not a number");
            case NumberStatus::OutOfRange:
                return fail(what + ": " + quoted(tokens[i]) + " is out of the range of a double");
            case NumberStatus::Ok:
                break;
            }
            if (i >= firstChecked && i <= lastChecked) {
                if (!std::isfinite(value))
                    return fail(what + " has a non-finite coordinate " + quoted(tokens[i]));
                if (std::abs(value) > limit)
                    return fail(what + ": " + quoted(tokens[i]) + " is beyond " + limitText);
                out[i - 1] = value;
            }
        }
        return {};
    }

    // v x y z [w] (or x y z r g b, a common extension): x y z are used, the rest must be numbers.
    std::string scanVertex(const std::vector<std::string_view>& tokens) {
        const size_t n = tokens.size() - 1;
        const std::string what = "vertex " + std::to_string(out_.positions.size() + 1);
        if (n < 3 || n > 7)
            return fail(what + " has " + counted(n, "number", "numbers") +
                        "; expected 'v x y z' (optionally w or r g b)");
        double xyz[3];
        if (std::string err = numbers(tokens, 1, 3, what, kMaxCoordinate, "+-1e5 m (mesh.h kMaxCoordinate)", xyz);
            !err.empty())
            return err;
        out_.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
        out_.sanitized += "v ";
        out_.sanitized +=
            std::string(tokens[1]) + " " + std::string(tokens[2]) + " " + std::string(tokens[3]);
        return {};
    }

    // vt u [v [w]]: v defaults to 0 as in tinyobjloader; w is ignored.
    std::string scanTexCoord(const std::vector<std::string_view>& tokens) {
        const size_t n = tokens.size() - 1;
        const std::string what = "texture coordinate " + std::to_string(out_.uvs.size() + 1);
        if (n < 1 || n > 3)
            return fail(what + " has " + counted(n, "number", "numbers") + "; expected 'vt u [v [w]]'");
        double uv[3] = {0, 0, 0};
        if (std::string err = numbers(tokens, 1, 2, what, kMaxUv, "+-1e6 (mesh.h kMaxUv)", uv); !err.empty())
            return err;
        out_.uvs.emplace_back(uv[0], uv[1]);
        out_.sanitized += "vt " + std::string(tokens[1]) + " " + (n >= 2 ? std::string(tokens[2]) : "0");
        return {};
    }

    // Resolves one index of a corner: 1-based, negative = relative to the data read so far.
    // Sets `resolved` (0-based); forward references are queued for the end-of-file check.
    std::string resolve(std::string_view corner, std::string_view token, size_t countSoFar, const char* what,
                        const char* plural, bool uv, long long& resolved) {
        long long value = 0;
        if (!parseIndex(token, value))
            return fail("face corner " + quoted(corner) + ": " + quoted(token) + " is not an integer index");
        if (value == 0)
            return fail("face corner " + quoted(corner) + ": index 0 is invalid (OBJ indices start at 1)");
        if (value < 0) {
            resolved = static_cast<long long>(countSoFar) + value;
            if (resolved < 0)
                return fail(std::string("face refers to ") + what + " " + std::to_string(value) + " but " +
                            defined(countSoFar, what, plural) + " before this line");
            return {};
        }
        if (value > std::numeric_limits<int>::max()) // tinyobjloader indices are int
            return fail(std::string("face refers to ") + what + " " + std::to_string(value) +
                        ", beyond any file");
        resolved = value - 1;
        if (static_cast<unsigned long long>(value) > countSoFar)
            forward_.push_back({line_, value, uv});
        return {};
    }

    // f c1 c2 c3 ... with each corner v, v/vt, v/vt/vn or v//vn.
    std::string scanFace(const std::vector<std::string_view>& tokens) {
        const size_t n = tokens.size() - 1;
        if (n < 3)
            return fail("face has " + counted(n, "vertex", "vertices") + "; a face needs at least 3");
        if (n > kMaxFaceCorners)
            return fail("face has " + std::to_string(n) + " vertices; at most " +
                        std::to_string(kMaxFaceCorners) + " are supported");
        std::vector<long long> vertices(n);
        size_t withUV = 0;
        for (size_t k = 0; k < n; ++k) {
            const std::string_view corner = tokens[k + 1];
            std::string_view parts[3];
            const size_t count = splitCorner(corner, parts);
            // Accepted: v (1 part), v/vt (2), v/vt/vn (3), v//vn (3, empty vt).
            const bool wellFormed = count <= 3 && !parts[0].empty() && (count != 2 || !parts[1].empty()) &&
                                    (count != 3 || !parts[2].empty());
            if (!wellFormed)
                return fail("malformed face corner " + quoted(corner) +
                            " (expected v, v/vt, v/vt/vn or v//vn)");
            if (std::string err = resolve(corner, parts[0], out_.positions.size(), "vertex", "vertices",
                                          false, vertices[k]);
                !err.empty())
                return err;
            if (count >= 2 && !parts[1].empty()) {
                long long t = 0;
                if (std::string err = resolve(corner, parts[1], out_.uvs.size(), "texture coordinate",
                                              "texture coordinates", true, t);
                    !err.empty())
                    return err;
                ++withUV;
            }
            if (count == 3) { // normals are ignored, but tinyobjloader refuses an index it cannot read
                long long normal = 0;
                if (!parseIndex(parts[2], normal) || normal == 0)
                    return fail("face corner " + quoted(corner) + ": normal index " + quoted(parts[2]) +
                                " is not a valid index");
            }
        }
        if (withUV != 0 && withUV != n)
            return fail("face mixes corners with and without texture coordinates");
        for (size_t a = 0; a < n; ++a)
            for (size_t b = a + 1; b < n; ++b)
                if (vertices[a] == vertices[b])
                    return fail("face uses vertex " + std::to_string(vertices[a] + 1) + " more than once");
        out_.faces.push_back({line_, n, withUV == n});
        out_.sanitized += "f";
        for (size_t k = 1; k < tokens.size(); ++k)
            out_.sanitized += " " + std::string(tokens[k]);
        return {};
    }

    const std::string& path_;
    Scan& out_;
    size_t line_ = 0;
    std::vector<ForwardIndex> forward_;
};

// ---- assemble -----------------------------------------------------------------------------------

// Same criterion as checkMesh: area below 1e-12 of the longest squared edge is zero area.
bool degenerate(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    const double scale = std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
    return scale == 0.0 || !(triangleArea(a, b, c) > 1e-12 * scale);
}
bool degenerateUv(const std::array<Vec2d, 3>& uv) {
    const double scale = std::max({(uv[1] - uv[0]).squaredNorm(), (uv[2] - uv[0]).squaredNorm(),
                                   (uv[2] - uv[1]).squaredNorm()});
    return !(std::abs(uvArea(uv[0], uv[1], uv[2])) > 1e-12 * scale);
}

// Planar UVs: project onto the two axes of largest bounding-box extent (kept in x, y, z order so an x-y
// mesh gets u = x, v = y), normalized to [0, 1] over the box of the vertices the faces use. A face
// standing edge-on to that plane (a fold, the side of a box) would get a texture triangle of no
// area, which no tear could split; it is projected onto the plane of its own normal's largest
// component instead, with the same normalization (a texture seam there, but a usable triangle).
void planarUVs(MeshData& mesh, const std::vector<bool>& needsPlanar) {
    Vec3d lo = Vec3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const auto& tri : mesh.triangles)
        for (Index v : tri) {
            lo = lo.cwiseMin(mesh.positions[v]);
            hi = hi.cwiseMax(mesh.positions[v]);
        }
    const Vec3d extent = hi - lo;
    int drop = 2; // on ties drop z, then y
    for (int i : {1, 0})
        if (extent[i] < extent[drop])
            drop = i;
    auto coord = [&](const Vec3d& p, int axis) {
        return extent[axis] > 0 ? (p[axis] - lo[axis]) / extent[axis] : 0.0;
    };
    auto project = [&](size_t t, int dropAxis) {
        const int a = dropAxis == 0 ? 1 : 0, b = dropAxis == 2 ? 1 : 2;
        for (int k = 0; k < 3; ++k) {
            const Vec3d& p = mesh.positions[mesh.triangles[t][k]];
            mesh.cornerUVs[t][k] = Vec2d(coord(p, a), coord(p, b));
        }
    };
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!needsPlanar[t])
            continue;
        project(t, drop);
        if (!degenerateUv(mesh.cornerUVs[t]))
            continue;
        const auto& tri = mesh.triangles[t];
        const Vec3d normal = (mesh.positions[tri[1]] - mesh.positions[tri[0]])
                                 .cross(mesh.positions[tri[2]] - mesh.positions[tri[0]])
                                 .cwiseAbs();
        int own = 0;
        for (int i : {1, 2})
            if (normal[i] > normal[own])
                own = i;
        project(t, own);
    }
}

// Fan-triangulates tinyobjloader's polygons (c0 c1 c2, c0 c2 c3, ...). The faces come out in file order,
// so the k-th polygon is the k-th `f` line of the scan.
std::string assemble(const std::string& path, const Scan& scan, MeshData& mesh) {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    std::istringstream stream(scan.sanitized);
    const bool loaded = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &stream, nullptr,
                                         /*triangulate=*/false, /*default_vcols_fallback=*/false);
    // `warn` (unknown material and the like) is ignored: the scan has already judged every line.
    if (!loaded || !err.empty()) {
        const std::string first = err.substr(0, err.find('\n'));
        return path + ": tinyobjloader: " + (first.empty() ? "could not read the file" : first);
    }
    const std::string disagree = ": internal error: tinyobjloader and the line scan disagree";
    if (attrib.vertices.size() != 3 * scan.positions.size() || attrib.texcoords.size() != 2 * scan.uvs.size())
        return path + disagree + " about the number of vertices";

    mesh.positions = scan.positions;
    std::vector<bool> needsPlanar;
    std::vector<size_t> triangleLine; // the `f` line each triangle came from
    size_t faceIndex = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        const std::vector<tinyobj::index_t>& idx = shape.mesh.indices;
        size_t offset = 0;
        for (const unsigned char corners : shape.mesh.num_face_vertices) {
            if (faceIndex >= scan.faces.size())
                return path + disagree + " about the number of faces";
            const ScannedFace& face = scan.faces[faceIndex++];
            if (corners != face.corners || offset + corners > idx.size())
                return atLine(path, face.line, disagree.substr(2) + " about this face");
            for (size_t k = 0; k < corners; ++k) {
                const tinyobj::index_t& c = idx[offset + k];
                const bool vOk = c.vertex_index >= 0 && size_t(c.vertex_index) < scan.positions.size();
                const bool tOk = face.hasUV
                                     ? (c.texcoord_index >= 0 && size_t(c.texcoord_index) < scan.uvs.size())
                                     : c.texcoord_index < 0;
                if (!vOk || !tOk)
                    return atLine(path, face.line, disagree.substr(2) + " about this face");
            }
            auto corner = [&](size_t k) { return idx[offset + k]; };
            for (size_t k = 1; k + 1 < corners; ++k) {
                const tinyobj::index_t c[3] = {corner(0), corner(k), corner(k + 1)};
                std::array<Index, 3> tri;
                std::array<Vec2d, 3> uv;
                for (int i = 0; i < 3; ++i) {
                    tri[i] = static_cast<Index>(c[i].vertex_index);
                    uv[i] = face.hasUV ? scan.uvs[size_t(c[i].texcoord_index)] : Vec2d::Zero();
                }
                if (degenerate(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]))
                    return atLine(path, face.line,
                                  corners == 3
                                      ? std::string("face is degenerate (zero area)")
                                      : "face is degenerate (fan triangle " + std::to_string(k) + " of " +
                                            std::to_string(corners - 2) + " has zero area)");
                mesh.triangles.push_back(tri);
                mesh.cornerUVs.push_back(uv);
                needsPlanar.push_back(!face.hasUV);
                triangleLine.push_back(face.line);
            }
            offset += corners;
        }
    }
    if (faceIndex != scan.faces.size())
        return path + disagree + " about the number of faces";
    planarUVs(mesh, needsPlanar);
    // The rest of checkMesh's criteria, here with the line of the face.
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const Vec3d &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &c = mesh.positions[tri[2]];
        const double shortest = std::sqrt(std::min({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()}));
        if (shortest < kMinEdge) {
            char len[32];
            std::snprintf(len, sizeof len, "%.3g", shortest);
            return atLine(path, triangleLine[t], std::string("face has an edge of ") + len +
                                                     " m; edges under 1e-7 m are refused");
        }
        if (degenerateUv(mesh.cornerUVs[t]))
            return atLine(path, triangleLine[t],
                          "face has texture coordinates with zero area (the texture cannot follow it when it tears)");
    }
    return {};
}

// ---- saveObj helpers ----------------------------------------------------------------------------

// %.17g without the C locale's say in the decimal point: exact round trip of every double.
void appendNumber(std::string& out, double x) {
    char buf[40];
    const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 17);
    out.append(buf, ec == std::errc() ? ptr : buf);
}

} // namespace

// ---- loadObj ------------------------------------------------------------------------------------

Result<MeshData> parseObj(std::string_view text, const std::string& source) {
    try {
        Scan scan;
        scan.sanitized.reserve(text.size());
        if (std::string err = Scanner(source, scan).run(text); !err.empty())
            return Result<MeshData>::failure(err);
        MeshData mesh;
        if (std::string err = assemble(source, scan, mesh); !err.empty())
            return Result<MeshData>::failure(err);
        // The scan names lines; checkMesh is the same net every other mesh source goes through.
        if (std::string err = checkMesh(mesh, source); !err.empty())
            return Result<MeshData>::failure(err);
        Result<MeshData> result;
        result.value = std::move(mesh);
        return result;
    } catch (const std::bad_alloc&) {
        return Result<MeshData>::failure(source + ": out of memory while reading");
    } catch (const std::exception& e) {
        return Result<MeshData>::failure(source + ": " + e.what());
    } catch (...) {
        return Result<MeshData>::failure(source + ": unexpected error while reading");
    }
}

Result<MeshData> loadObj(const std::string& path) {
    std::string text;
    try {
        const FileLimits limits{kMaxObjBytes, "an OBJ file",
                                "the importer reads at most " + std::to_string(kMaxObjBytes >> 20) +
                                    " MiB (a cloth of about 850 x 850 particles)"};
        if (std::string err = readWholeFile(path, text, limits); !err.empty())
            return Result<MeshData>::failure(err);
    } catch (const std::bad_alloc&) {
        return Result<MeshData>::failure(path + ": out of memory while reading");
    } catch (const std::exception& e) {
        return Result<MeshData>::failure(path + ": " + e.what());
    }
    return parseObj(text, path);
}

// ---- saveObj ------------------------------------------------------------------------------------

// v lines (full precision), one vt per triangle corner (corner UVs are not shared between triangles, so
// a seam needs no special case), f v/vt lines. Returns false (and leaves no partial file) on failure.
bool saveObj(const MeshData& mesh, const std::string& path) {
    try {
        if (mesh.cornerUVs.size() != mesh.triangles.size())
            return false;
        for (const auto& tri : mesh.triangles)
            for (Index v : tri)
                if (v >= mesh.positions.size())
                    return false;
        std::string out = "# clothtear mesh: " + std::to_string(mesh.positions.size()) + " vertices, " +
                          std::to_string(mesh.triangles.size()) + " triangles\n";
        out.reserve(out.size() + 64 * mesh.positions.size() + 100 * mesh.triangles.size());
        for (const Vec3d& p : mesh.positions) {
            out += "v";
            for (int i = 0; i < 3; ++i) {
                out += ' ';
                appendNumber(out, p[i]);
            }
            out += '\n';
        }
        for (const auto& uvs : mesh.cornerUVs)
            for (const Vec2d& uv : uvs) {
                out += "vt ";
                appendNumber(out, uv.x());
                out += ' ';
                appendNumber(out, uv.y());
                out += '\n';
            }
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            out += "f";
            for (int k = 0; k < 3; ++k) {
                out += ' ';
                out += std::to_string(mesh.triangles[t][k] + 1);
                out += '/';
                out += std::to_string(3 * t + k + 1);
            }
            out += '\n';
        }
        std::FILE* file = std::fopen(path.c_str(), "wb");
        if (!file)
            return false;
        bool ok = std::fwrite(out.data(), 1, out.size(), file) == out.size();
        ok = (std::fclose(file) == 0) && ok;
        if (!ok)
            std::remove(path.c_str());
        return ok;
    } catch (...) {
        return false;
    }
}

} // namespace clothtear
