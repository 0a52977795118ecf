#include "rsr/embedding.h"

#include "rsr/face_split.h"

namespace hrsr::rsr {

void Embedding::record_triangle(const LocalTriangle& t, std::vector<LocalTriangle>& list) {
    count_triangle_edge(rotation, t[0], t[1]);
    count_triangle_edge(rotation, t[1], t[2]);
    count_triangle_edge(rotation, t[2], t[0]);
    faces.mark_recorded_triangle(t[0], t[1]);
    list.push_back(t);
}

} // namespace hrsr::rsr
