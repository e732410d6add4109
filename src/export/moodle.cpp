#include "export/moodle.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

#include "check/judge.hpp"
#include "core/input_error.hpp"
#include "export/html_text.hpp"
#include "export/message_numbers.hpp"

namespace wobble::exports {

namespace {
// Moodle's tolerance types (question/type/numerical): 1 relative, 2 nominal (absolute).
constexpr int kRelative = 1, kNominal = 2;
// The correct answer as Moodle shows it: 2 = significant figures, 6 of them.
constexpr int kSignificantFigures = 2, kShownFigures = 6;

// The shortest text that reads back as the same double (what a student sees in the values).
std::string number(double x) { return fmt::format("{}", x == 0.0 ? 0.0 : x); }

std::string cdata(const std::string& text) {
  // "]]>" cannot appear inside CDATA: split it across two sections.
  std::string out = "<![CDATA[";
  std::size_t from = 0, at;
  while ((at = text.find("]]>", from)) != std::string::npos) {
    out += text.substr(from, at - from) + "]]]]><![CDATA[>";
    from = at + 3;
  }
  return out + text.substr(from) + "]]>";
}

std::string text_element(const std::string& tag, const std::string& text, bool html = false) {
  return fmt::format("<{0}{1}><text>{2}</text></{0}>", tag, html ? " format=\"html\"" : "",
                     html ? cdata(text) : html_escape(text));
}

// A problem's text with each brace as the entity &#123;: the same brace to the browser and
// MathJax, but no wildcard to Moodle, which substitutes {name} (\theta_{ans} would show the
// answer) and offers each {word} (\mathrm{min}) as a wildcard when the question is edited.
std::string no_wildcards(const std::string& html) {
  std::string out;
  for (const char c : html) out += c == '{' ? std::string("&#123;") : std::string(1, c);
  return out;
}

// A wildcard Moodle substitutes in the question text: letters, digits, underscores.
std::string wildcard(const std::string& name) {
  std::string out = "p_";
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return out;
}

// "0.52 kg" -> ("0.52", "kg"); "22°" -> ("22", "°").
std::pair<std::string, std::string> split_value(const std::string& shown) {
  const std::string degree = "°";
  if (shown.size() > degree.size() &&
      shown.compare(shown.size() - degree.size(), degree.size(), degree) == 0) {
    return {shown.substr(0, shown.size() - degree.size()), degree};
  }
  const auto space = shown.find(' ');
  if (space == std::string::npos) return {shown, ""};
  return {shown.substr(0, space), shown.substr(space + 1)};
}

struct Dataset {
  std::string name;
  std::vector<double> items;  ///< one per variant
  std::vector<std::string> shown;  ///< the items as the handout shows them (else number())
};

std::string dataset_xml(const Dataset& d) {
  std::string items;
  for (std::size_t i = 0; i < d.items.size(); ++i) {
    items += fmt::format("<dataset_item><number>{}</number><value>{}</value></dataset_item>\n",
                         i + 1, d.shown.empty() ? number(d.items[i]) : d.shown[i]);
  }
  const auto [lo, hi] = std::minmax_element(d.items.begin(), d.items.end());
  return fmt::format(
      "<dataset_definition>\n<status><text>private</text></status>\n<name><text>{}</text></name>\n"
      "<type>calculated</type>\n<distribution><text>uniform</text></distribution>\n"
      "<minimum><text>{}</text></minimum>\n<maximum><text>{}</text></maximum>\n"
      "<decimals><text>10</text></decimals>\n<itemcount>{}</itemcount>\n"
      "<dataset_items>\n{}</dataset_items>\n<number_of_items>{}</number_of_items>\n"
      "</dataset_definition>\n",
      d.name, number(*lo), number(*hi), d.items.size(), items, d.items.size());
}

std::string answer_xml(int fraction, const std::string& formula, double tolerance, int type,
                       const std::string& feedback) {
  return fmt::format(
      "<answer fraction=\"{}\">\n<text>{}</text>\n<tolerance>{}</tolerance>\n"
      "<tolerancetype>{}</tolerancetype>\n<correctanswerformat>{}</correctanswerformat>\n"
      "<correctanswerlength>{}</correctanswerlength>\n{}\n</answer>\n",
      fraction, formula, number(tolerance), type, kSignificantFigures, kShownFigures,
      text_element("feedback", feedback, true));
}

std::string entry_words(const Answer& a, std::size_t e) {
  if (a.value.data.size() == 1) return "";
  if (a.kind == AnswerKind::principal_moments && a.value.data.size() == 3) {
    return std::array<const char*, 3>{", the smallest moment", ", the middle moment",
                                      ", the largest moment"}[e];
  }
  if (a.value.shape == Value::Shape::vector) {
    // "c₁" as the question names it; "its e₁ component" along the body's axes.
    const std::vector<std::string> names = entry_names(a);
    if (names.size() != a.value.data.size()) return fmt::format(", entry {}", e + 1);
    return a.named_entries.empty() ? fmt::format(", its {} component", names[e]) : ", " + names[e];
  }
  return fmt::format(", entry ({}, {})", e / a.value.cols + 1, e % a.value.cols + 1);
}

struct Question {
  const Problem& problem;
  const VariantSet& set;
  std::size_t answer;  ///< index into each variant's answers
  std::size_t entry;
};

std::string question_text(const Question& q) {
  const GradedVariant& first = q.set.variants.front();
  const GradedAnswer& g = first.answers[q.answer];
  std::string html = no_wildcards(statement_html(q.problem.statement, "\\(", "\\)"));
  html += "<p>Your values (variant {variant}):</p>\n<table>\n";
  for (const auto& [name, shown] : first.values) {
    std::string latex = name;
    for (const auto& p : first.key.parameters) {
      if (p.name == name) latex = p.latex;
    }
    const std::string unit = split_value(shown).second;
    html += fmt::format("<tr><td>\\({}\\)</td><td>{{{}}}{}{}</td></tr>\n",
                        no_wildcards(html_escape(latex)), wildcard(name),
                        unit == "°" || unit.empty() ? "" : " ", html_escape(unit));
  }
  html += "</table>\n";
  for (const auto& part : first.key.parts) {
    if (part.id == g.part) {
      html += fmt::format("<p><strong>({})</strong> {}</p>\n", part.id,
                          no_wildcards(inline_html(part.question, "\\(", "\\)")));
    }
  }
  html += fmt::format("<p>Give <code>{}</code>{}{}.</p>\n", html_escape(g.answer.name),
                      entry_words(g.answer, q.entry),
                      asked_unit(g.answer).empty() ? "" : " in " + unit_html(asked_unit(g.answer)));
  return html;
}

// The part's hint: in Moodle's interactive behaviour, shown after a wrong try, with one more try
// (Moodle allows one try, and one more per hint).
std::string hint_xml(const Question& q) {
  const std::string& hint = q.problem.hint(q.set.variants.front().answers[q.answer].part);
  return hint.empty()
             ? ""
             : text_element("hint", no_wildcards(inline_html(hint, "\\(", "\\)")), true) + "\n";
}

// A mistake as one 0% answer: its wrong value per variant, and its message with each number
// that differs between variants as a wildcard of its own, which Moodle substitutes in an
// answer's feedback as in the text (one answer for "16.2% below" in one variant and "41.2%
// below" in another, not one per variant).
struct MistakeAnswer {
  Dataset values;                ///< "m1": the wrong value in each variant
  std::vector<Dataset> numbers;  ///< "m1_1", ..: the message's numbers that differ
  std::string feedback;          ///< the message, with {m1_1}, .. in those numbers' places
};

// The mistakes of the question's entry in wobble's order, the k-th of one message but for its
// numbers in each variant together (a factor 2 off and a factor 4 off are one message so: the
// first and the second of it). Where a variant does not have one (equal to the key there, or
// named as an earlier mistake), its value is the right one, which the right answer, tried
// first, takes, and its numbers the first variant's that has it (never shown).
std::vector<MistakeAnswer> mistake_answers(const Question& q, const Dataset& right) {
  struct Seen {
    MessageNumbers words;
    std::size_t ordinal;  // the k-th of its words in a variant
    std::vector<double> values;
    std::vector<std::vector<std::string>> numbers;  // per variant; empty where it has none
    std::vector<bool> has;
  };
  const auto& variants = q.set.variants;
  std::vector<Seen> seen;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    std::vector<std::vector<std::string>> before;  // this variant's messages' words so far
    for (const auto& m : variants[i].answers[q.answer].mistakes) {
      MessageNumbers words = message_numbers(m.message);
      const auto ordinal =
          static_cast<std::size_t>(std::count(before.begin(), before.end(), words.words));
      before.push_back(words.words);
      auto it = std::find_if(seen.begin(), seen.end(), [&](const Seen& s) {
        return s.words.words == words.words && s.ordinal == ordinal;
      });
      if (it == seen.end()) {
        seen.push_back({words, ordinal, right.items,
                        std::vector<std::vector<std::string>>(variants.size()),
                        std::vector<bool>(variants.size(), false)});
        it = seen.end() - 1;
      }
      it->values[i] = m.values[q.entry];
      it->numbers[i] = words.numbers;
      it->has[i] = true;
    }
  }
  std::vector<MistakeAnswer> out;
  for (const Seen& s : seen) {
    MistakeAnswer a{{fmt::format("m{}", out.size() + 1), s.values, {}}, {}, {}};
    const std::size_t first =
        static_cast<std::size_t>(std::find(s.has.begin(), s.has.end(), true) - s.has.begin());
    std::vector<std::string> in_place = s.numbers[first];
    for (std::size_t k = 0; k < in_place.size(); ++k) {
      Dataset d{fmt::format("{}_{}", a.values.name, k + 1), {}, {}};
      bool differs = false;
      for (std::size_t i = 0; i < variants.size(); ++i) {
        const std::string& n = s.has[i] ? s.numbers[i][k] : s.numbers[first][k];
        differs = differs || n != s.numbers[first][k];
        d.shown.push_back(n);
        d.items.push_back(std::strtod(n.c_str(), nullptr));  // digits as the judge printed them
      }
      if (!differs) continue;
      in_place[k] = "{" + d.name + "}";
      a.numbers.push_back(std::move(d));
    }
    a.feedback = with_numbers(s.words, in_place);
    out.push_back(std::move(a));
  }
  return out;
}

std::string question_xml(const Question& q) {
  const auto& variants = q.set.variants;
  const GradedAnswer& g0 = variants.front().answers[q.answer];
  std::vector<Dataset> datasets;
  Dataset variant{"variant", {}, {}}, right{"ans", {}, {}};
  double smallest_scale = std::numeric_limits<double>::infinity();
  bool any_zero = false;
  for (const auto& v : variants) {
    const GradedAnswer& g = v.answers[q.answer];
    const double k = g.answer.value.data[q.entry];
    variant.items.push_back(static_cast<double>(v.number));
    right.items.push_back(k);
    any_zero = any_zero || k == 0.0;
    smallest_scale = std::min(smallest_scale, k != 0.0 ? std::abs(k) : g.zero_scale);
  }
  datasets.push_back(variant);
  for (std::size_t p = 0; p < variants.front().values.size(); ++p) {
    Dataset d{wildcard(variants.front().values[p].first), {}, {}};
    for (const auto& v : variants) {
      d.shown.push_back(split_value(v.values[p].second).first);
      d.items.push_back(std::stod(d.shown.back()));
    }
    datasets.push_back(d);
  }
  datasets.push_back(right);
  const std::vector<MistakeAnswer> mistakes = mistake_answers(q, right);
  // wobble judges a zero against the largest value of its unit: Moodle's relative tolerance
  // cannot, so a question with a zero in some variant takes the nominal tolerance of its
  // smallest scale.
  const int type = any_zero ? kNominal : kRelative;
  const double tolerance = any_zero ? g0.rel_tol * smallest_scale : g0.rel_tol;
  std::string answers = answer_xml(100, "{ans}", tolerance, type, "correct");
  // An Euler angle a turn either way is the same angle (wobble check takes any whole number of
  // turns; one answer per turn here, a turn either way covering a course's other range).
  if (check::angles_up_to_turns(g0.answer)) {
    for (const char* turn : {"{ans} + 2*pi()", "{ans} - 2*pi()"})
      answers += answer_xml(100, turn, tolerance, type,
                            "correct (a whole turn from the key's: the same angle)");
  }
  for (const auto& m : mistakes) {
    // A mistake that leaves this entry right in every variant (the reversed sign of a zero
    // entry) is no answer of its own here.
    if (m.values.items == right.items) continue;
    answers +=
        answer_xml(0, "{" + m.values.name + "}", tolerance, type, "incorrect: " + m.feedback);
    datasets.push_back(m.values);
    datasets.insert(datasets.end(), m.numbers.begin(), m.numbers.end());
  }
  std::string defs;
  for (const auto& d : datasets) defs += dataset_xml(d);
  return fmt::format(
      "<question type=\"calculated\">\n{}\n{}\n{}\n<defaultgrade>1</defaultgrade>\n"
      "<penalty>0.3333333</penalty>\n<hidden>0</hidden>\n<synchronize>0</synchronize>\n"
      "<single>0</single>\n<answernumbering>abc</answernumbering>\n"
      "<shuffleanswers>0</shuffleanswers>\n{}\n{}\n{}\n{}<unitgradingtype>0</unitgradingtype>\n"
      "<unitpenalty>0.1000000</unitpenalty>\n<showunits>3</showunits>\n<unitsleft>0</unitsleft>\n"
      "<dataset_definitions>\n{}</dataset_definitions>\n{}</question>\n",
      text_element("name", fmt::format("{} ({}) {}{}", q.problem.id, g0.part, g0.answer.name,
                                       entry_words(g0.answer, q.entry))),
      text_element("questiontext", question_text(q), true),
      text_element("generalfeedback", "", true), text_element("correctfeedback", "", true),
      text_element("partiallycorrectfeedback", "", true),
      text_element("incorrectfeedback", "", true), answers, defs, hint_xml(q));
}
}  // namespace

MoodleQuiz moodle_quiz(const Problem& problem, const VariantSet& set,
                       const check::Options& options) {
  if (options.sigfigs) {
    throw InputError(
        "--sigfigs: Moodle's calculated questions grade within a tolerance, not by significant "
        "figures; give --tolerance instead");
  }
  MoodleQuiz quiz;
  std::string body;
  const auto& answers = set.variants.front().answers;
  for (std::size_t j = 0; j < answers.size(); ++j) {
    const Answer& a = answers[j].answer;
    if (a.kind == AnswerKind::principal_axes) {
      quiz.left_out.push_back(fmt::format(
          "{} (part {}): principal axes are right up to sign (a degenerate pair anywhere in its "
          "plane), which a Moodle number cannot check; the PrairieLearn and Gradescope exports "
          "grade them",
          a.name, answers[j].part));
      continue;
    }
    for (std::size_t e = 0; e < a.value.data.size(); ++e) {
      body += question_xml({problem, set, j, e});
      ++quiz.questions;
    }
  }
  quiz.xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n<question type=\"category\">\n" +
             text_element("category", "$course$/top/wobble/" + problem.id) +
             "\n</question>\n" + body + "</quiz>\n";
  return quiz;
}

}  // namespace wobble::exports
