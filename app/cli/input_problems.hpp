#pragma once
// How every command shows bad input: one "error: file:line: key = value: reason" per problem.

#include <iostream>

#include "legofeup/lessons/input_error.hpp"

namespace legofeup::cli {

inline void report_problems(const lessons::InputError& error) {
    for (const lessons::InputProblem& problem : error.problems()) {
        std::cerr << "error: " << problem.message() << '\n';
    }
}

}  // namespace legofeup::cli
