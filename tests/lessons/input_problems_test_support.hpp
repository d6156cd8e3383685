#pragma once
// What a reader refused: the problems of the InputError an action throws.

#include <string>
#include <vector>

#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons::testing {

/// The problems of an InputError thrown by `action` (none if it did not throw).
template <class Action>
std::vector<InputProblem> input_problems_of(Action action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.problems();
    }
    return {};
}

/// Every problem's message, one a line: what a failing expectation prints.
inline std::string all_messages(const std::vector<InputProblem>& problems) {
    std::string text;
    for (const InputProblem& problem : problems) {
        text += problem.message() + "\n";
    }
    return text;
}

}  // namespace legofeup::lessons::testing
