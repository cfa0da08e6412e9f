// OBJ import/export (placeholder until the importer is written).
#include "clothtear/mesh.h"

namespace clothtear {
Result<MeshData> loadObj(const std::string& path) { return Result<MeshData>::failure(path + ": OBJ import not built yet"); }
bool saveObj(const MeshData&, const std::string&) { return false; }
} // namespace clothtear
