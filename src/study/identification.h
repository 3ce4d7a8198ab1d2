// Identification statistics (docs/study.md, "Identification"): one of K stimuli shown, the
// participant names one of K answers; the confusion matrix of counts, percent correct and the
// information transferred, in bits (Shannon 1948; Miller & Nicely 1955), with the Miller-Madow
// small-sample bias correction (Miller 1955), and 2^IT: the number of stimuli the participant
// tells apart without error that carry the same information.
#pragma once

#include <vector>

namespace ps::study {

class ConfusionMatrix {
 public:
  ConfusionMatrix(int stimuli, int responses);  // rows: shown; columns: answered
  explicit ConfusionMatrix(std::vector<std::vector<int>> counts);

  void add(int shown, int answered, int count = 1);
  int count(int shown, int answered) const { return counts_[shown][answered]; }
  int stimuli() const { return static_cast<int>(counts_.size()); }
  int responses() const { return counts_.empty() ? 0 : static_cast<int>(counts_[0].size()); }
  int total() const;

 private:
  std::vector<std::vector<int>> counts_;
};

struct IdentificationStats {
  int trials = 0;
  double percent_correct = 0.0;  // the diagonal's share, x 100 (stimulus i answered as i)
  // I = sum_ij (n_ij / N) log2(n_ij N / (n_i. n_.j)): the plug-in ("maximum-likelihood") estimate.
  double information_bits = 0.0;
  // The Miller-Madow term (Miller 1955): each plug-in entropy falls short by (m - 1) / (2N ln 2),
  // m its cells of non-zero probability, so I = H(row) + H(col) - H(cell) is off by
  // (m_row + m_col - m_cell - 1) / (2N ln 2). m_row and m_col: the rows and columns with counts;
  // m_cell = m_row x m_col, every confusion between them deemed possible (counting only the
  // occupied cells under-corrects a sparse matrix: docs/study.md, "Identification"). The term
  // is then -(m_row - 1)(m_col - 1) / (2N ln 2).
  double miller_madow_bits = 0.0;
  // information_bits + miller_madow_bits, clamped to [0, log2 min(m_row, m_col)].
  double corrected_bits = 0.0;
  double distinguishable = 1.0;  // 2^corrected_bits
};

IdentificationStats identification_stats(const ConfusionMatrix& m);

}  // namespace ps::study
