#include "Suggest.h"

#include <algorithm>
#include <vector>

namespace m3gcli {

namespace {

std::string_view withoutDashes(std::string_view s) {
    while (!s.empty() && s.front() == '-') s.remove_prefix(1);
    return s;
}

}  // namespace

std::size_t editDistance(std::string_view a, std::string_view b) {
    const std::size_t n = a.size(), m = b.size();
    // Three rows: the transposition looks two rows back.
    std::vector<std::size_t> prev2(m + 1), prev(m + 1), cur(m + 1);
    for (std::size_t j = 0; j <= m; ++j) prev[j] = j;
    for (std::size_t i = 1; i <= n; ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                cur[j] = std::min(cur[j], prev2[j - 2] + 1);
        }
        std::swap(prev2, prev);
        std::swap(prev, cur);
    }
    return prev[m];
}

std::optional<std::string> closestName(std::string_view word, std::span<const std::string> candidates) {
    if (const auto eq = word.find('='); eq != std::string_view::npos && word.starts_with("--")) word = word.substr(0, eq);
    const std::string_view bare = withoutDashes(word);
    if (bare.empty()) return std::nullopt;
    const std::string* best = nullptr;
    std::size_t bestDistance = 0;
    const std::string* prefixOf = nullptr;
    int prefixes = 0;
    for (const std::string& c : candidates) {
        const std::string_view cb = withoutDashes(c);
        const std::size_t d = editDistance(bare, cb);
        if (!best || d < bestDistance) {
            best = &c;
            bestDistance = d;
        }
        if (bare.size() >= 3 && cb.starts_with(bare)) {
            prefixOf = &c;
            ++prefixes;
        }
    }
    if (!best) return std::nullopt;
    const std::size_t limit = std::max<std::size_t>(2, bare.size() / 3);
    if (bestDistance <= limit && bestDistance < bare.size()) return *best;
    if (prefixes == 1) return *prefixOf;
    return std::nullopt;
}

}  // namespace m3gcli
