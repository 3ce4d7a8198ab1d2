# The outside check of the psychometric fit (docs/study.md, "The outside check against R"):
# R's own maximum-likelihood fit, glm(), of the same trials the C++ fit saw.
#
#   Rscript --vanilla glm_fit.R COUNTS.csv SHAPE GUESS CRITERION
#
# COUNTS.csv has columns level,trials,correct. SHAPE is logistic or normal (glm's logit and
# probit links), GUESS the guess rate gamma (0: yes/no, plain glm; 0.5: 2AFC, through a link of
# its own, psi = gamma + (1 - gamma) F(eta)), CRITERION the proportion correct the threshold is
# read at. No lapse: glm has no parameter for it, so the C++ side fits with the lapse fixed at 0.
# Prints one line: "threshold T slope S b0 B0 b1 B1 deviance D converged TRUE".
args <- commandArgs(trailingOnly = TRUE)
if (length(args) != 4) stop("usage: glm_fit.R COUNTS.csv logistic|normal GUESS CRITERION")
d <- read.csv(args[1])
shape <- args[2]
guess <- as.numeric(args[3])
criterion <- as.numeric(args[4])

base <- switch(shape, logistic = "logit", normal = "probit", stop("shape must be logistic or normal"))
if (guess == 0) {
  link <- make.link(base)
} else {
  # The m-AFC link: F's quantile and density from R's own distributions.
  q <- if (shape == "logistic") qlogis else qnorm
  p <- if (shape == "logistic") plogis else pnorm
  dens <- if (shape == "logistic") dlogis else dnorm
  link <- structure(list(
    linkfun = function(mu) q((mu - guess) / (1 - guess)),
    linkinv = function(eta) guess + (1 - guess) * p(eta),
    mu.eta = function(eta) (1 - guess) * dens(eta),
    valideta = function(eta) TRUE,
    name = paste0(base, "-", guess)), class = "link-glm")
}

y <- d$correct / d$trials
# Starting proportions inside (guess, 1): the link is undefined at or below the guess rate.
mustart <- pmin(pmax(y, guess + 0.5 * (1 - guess) * 0.1), 1 - 0.5 * (1 - guess) * 0.1)
fit <- glm(cbind(correct, trials - correct) ~ level, data = d, family = binomial(link = link),
           mustart = mustart, control = glm.control(epsilon = 1e-12, maxit = 200))
b <- coef(fit)
# The level where psi reaches the criterion, and psi's slope there, from the fitted linear predictor.
eta <- link$linkfun(criterion)
threshold <- (eta - b[[1]]) / b[[2]]
slope <- link$mu.eta(eta) * b[[2]]
cat(sprintf("threshold %.10g slope %.10g b0 %.10g b1 %.10g deviance %.10g converged %s\n",
            threshold, slope, b[[1]], b[[2]], deviance(fit), fit$converged))
