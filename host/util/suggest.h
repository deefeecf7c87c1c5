// "Did you mean": the nearest of the words a message could have meant, for scene errors and
// command-line usage errors.
#pragma once

#include <string>
#include <vector>

// Levenshtein distance of a and b, or 3 when it is more than 2 (the only question asked).
size_t editDistanceUpTo2(const std::string& a, const std::string& b);

// The candidate within edit distance 2 of `word` (the closest; the first of equals), or "".
std::string nearestWord(const std::string& word, const std::vector<std::string>& candidates);

// " (did you mean 'X'?)" for the nearest candidate, or "" when none is within distance 2.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);
