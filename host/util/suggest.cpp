#include "suggest.h"

#include <algorithm>

size_t editDistanceUpTo2(const std::string& a, const std::string& b) {
  if ((a.size() > b.size() ? a.size() - b.size() : b.size() - a.size()) > 2) return 3;
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return std::min<size_t>(row[b.size()], 3);
}

std::string nearestWord(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t bestDistance = 3;
  for (const std::string& c : candidates) {
    const size_t d = c == word ? 3 : editDistanceUpTo2(word, c);
    if (d < bestDistance) best = c, bestDistance = d;
  }
  return best;
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string near = nearestWord(word, candidates);
  return near.empty() ? std::string() : " (did you mean '" + near + "'?)";
}
