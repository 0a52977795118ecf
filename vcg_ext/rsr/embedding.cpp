#include "rsr/embedding.h"

#include "rsr/face_split.h"

namespace hrsr::rsr {

void Embedding::record_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    count_triangle_edge(rotation, a, b);
    count_triangle_edge(rotation, b, c);
    count_triangle_edge(rotation, c, a);
    faces.mark_recorded_triangle(a, b);
    triangles.push_back({a, b, c});
}

} // namespace hrsr::rsr
