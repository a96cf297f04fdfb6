#include <m3g/skin/InfluenceTable.h>

#include <algorithm>
#include <stdexcept>

namespace m3g::skin {

namespace {
// Larger accumulated weight first; on ties the bone added first wins.
bool before(std::int64_t wa, std::int32_t ba, std::int64_t wb, std::int32_t bb) noexcept {
    return wa != wb ? wa > wb : ba < bb;
}
}  // namespace

InfluenceTable::InfluenceTable(int maxInfluences) : n_(maxInfluences) {
    if (maxInfluences < 1) throw std::invalid_argument("InfluenceTable: maxInfluences must be >= 1");
}

void InfluenceTable::ensureVertices(int count) {
    if (count <= vertexCount_) return;
    const std::size_t size = static_cast<std::size_t>(count) * n_;
    bones_.resize(size, -1);
    weights_.resize(size, 0.0f);
    raw_.resize(size, 0);
    vertexCount_ = count;
}

int InfluenceTable::count(int v) const noexcept {
    if (v < 0 || v >= vertexCount_) return 0;
    int c = 0;
    while (c < n_ && bones_[static_cast<std::size_t>(v) * n_ + c] >= 0) ++c;
    return c;
}

int InfluenceTable::rigidBone(std::size_t vertices) const noexcept {
    if (vertices == 0 || vertices > static_cast<std::size_t>(vertexCount_)) return -1;
    const int first = bone(0, 0);
    // A vertex's weights are normalised over its filled slots: one slot
    // has weight 1 exactly.
    for (std::size_t i = 0; i < vertices; ++i) {
        const int v = static_cast<int>(i);
        if (count(v) != 1 || bone(v, 0) != first || weight(v, 0) != 1.0f) return -1;
    }
    return first;
}

void InfluenceTable::rebuildVertex(int v) {
    // Sort the candidate influences and keep the N best; normalise over them.
    const std::size_t base = static_cast<std::size_t>(v) * n_;
    auto it = overflow_.find(v);
    if (it != overflow_.end()) {
        auto& all = it->second;
        std::sort(all.begin(), all.end(),
                  [](const Influence& a, const Influence& b) { return before(a.weight, a.bone, b.weight, b.bone); });
        for (int k = 0; k < n_; ++k) {
            bones_[base + k] = all[k].bone;
            raw_[base + k] = all[k].weight;
        }
    } else {
        // Insertion sort of at most N slots.
        for (int i = 1; i < n_ && bones_[base + i] >= 0; ++i)
            for (int j = i; j > 0 && before(raw_[base + j], bones_[base + j], raw_[base + j - 1], bones_[base + j - 1]);
                 --j) {
                std::swap(raw_[base + j], raw_[base + j - 1]);
                std::swap(bones_[base + j], bones_[base + j - 1]);
            }
    }
    std::int64_t sum = 0;
    for (int k = 0; k < n_ && bones_[base + k] >= 0; ++k) sum += raw_[base + k];
    for (int k = 0; k < n_; ++k)
        weights_[base + k] = bones_[base + k] >= 0 && sum > 0 ? static_cast<float>(
                                                                   static_cast<double>(raw_[base + k]) / sum)
                                                             : 0.0f;
}

void InfluenceTable::add(int bone, std::int32_t weight, int first, int count) {
    if (bone < 0 || weight <= 0 || first < 0 || count <= 0 || static_cast<long long>(first) + count > 65535)
        throw std::invalid_argument("InfluenceTable::add: bone >= 0, weight > 0, count > 0, range within 65535");
    ensureVertices(first + count);
    boneCount_ = std::max(boneCount_, bone + 1);
    ++revision_;
    for (int v = first; v < first + count; ++v) {
        const std::size_t base = static_cast<std::size_t>(v) * n_;
        auto over = overflow_.find(v);
        if (over != overflow_.end()) {
            auto& all = over->second;
            auto hit = std::find_if(all.begin(), all.end(), [&](const Influence& i) { return i.bone == bone; });
            if (hit != all.end())
                hit->weight += weight;
            else
                all.push_back({bone, weight});
            rebuildVertex(v);
            continue;
        }
        int k = 0;
        while (k < n_ && bones_[base + k] >= 0 && bones_[base + k] != bone) ++k;
        if (k < n_) {
            if (bones_[base + k] == bone) {
                raw_[base + k] += weight;
            } else {
                bones_[base + k] = bone;
                raw_[base + k] = weight;
            }
        } else {
            // More than N distinct bones: keep every influence from now on so
            // that the top-N stays exact under later accumulation.
            std::vector<Influence> all;
            all.reserve(n_ + 1);
            for (int s = 0; s < n_; ++s) all.push_back({bones_[base + s], raw_[base + s]});
            all.push_back({bone, weight});
            overflow_.emplace(v, std::move(all));
        }
        rebuildVertex(v);
    }
}

int InfluenceTable::boneVertices(int bone, std::vector<int>* vertices, std::vector<float>* weights) const {
    int found = 0;
    for (int v = 0; v < vertexCount_; ++v) {
        const std::size_t base = static_cast<std::size_t>(v) * n_;
        for (int k = 0; k < n_ && bones_[base + k] >= 0; ++k) {
            if (bones_[base + k] != bone) continue;
            ++found;
            if (vertices) vertices->push_back(v);
            if (weights) weights->push_back(weights_[base + k]);
            break;
        }
    }
    return found;
}

}  // namespace m3g::skin
